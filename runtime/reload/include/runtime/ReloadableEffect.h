// ReloadableEffect: the hot-reload loop of the viewer, without a window. In the `reload` library, not
// `render`: it compiles source, so it links the compiler (fx), which the effect runtime itself does not.
// Owns the last good EffectRenderer of an effect file (source, or a compiled effect file that each
// reload reads again), a CompileCache shared by every reload (a pass whose generated HLSL
// did not change is not recompiled) and a FileWatcher on the effect and every file it includes.
//
// A reload that fails (parse, compile or link error) changes nothing that renders: the last good
// renderer stays, and diagnostics() holds the errors ("file:line:column: message") for the overlay and
// stderr. A reload that succeeds replaces the renderer and carries over every parameter the user set
// (EffectRenderer::isPinned) that still exists with the same type.
//
// Made with an EffectPool (runtime/EffectPool.h), every renderer it loads is created in that pool: a reload
// stays a member, and its `shared` parameters take the pool's current values, which the other effects may
// have set since the last load, rather than the old renderer's. An edit that declares a shared parameter
// with another type than the pool's fails like any broken edit.
//
// Needs a current GL context for reload(), reloadIfChanged() and the renderer's whole life.
#pragma once

#include <fx/CompileCache.h>
#include <fx/Diagnostics.h>
#include <fx/EffectParser.h>
#include <runtime/EffectPool.h>
#include <runtime/EffectRenderer.h>
#include <runtime/FileWatcher.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace runtime {

class ReloadableEffect {
public:
    enum class Result { Unchanged, Reloaded, Failed };

    // What the last reload() spent where, and what the compile cache did in it.
    struct ReloadStats {
        double parseMs = 0.0;
        double compileMs = 0.0;  // HLSL -> GLSL for the passes the cache did not have
        double createMs = 0.0;   // EffectRenderer::create: GL programs, textures, samplers
        size_t cacheHits = 0;    // stages reused from the compile cache
        size_t cacheMisses = 0;  // stages compiled
    };

    explicit ReloadableEffect(std::string path, fx::ParseOptions parseOptions = {},
                              std::shared_ptr<EffectPool> pool = nullptr);
    ~ReloadableEffect();
    ReloadableEffect(const ReloadableEffect&) = delete;
    ReloadableEffect& operator=(const ReloadableEffect&) = delete;

    // Parses, compiles and creates the renderer now; on success swaps it in. Re-targets the watcher at
    // the files the new parse opened (an edit may add an include). Returns false on any error.
    bool reload();

    // Waits up to `timeout` for a save of the effect or one of its includes (debounced, see FileWatcher)
    // and reloads if there was one. A zero timeout polls: what a render loop calls once per frame.
    Result reloadIfChanged(std::chrono::milliseconds timeout = std::chrono::milliseconds(0),
                           std::chrono::milliseconds debounce = std::chrono::milliseconds(50));

    // The last good renderer; nullptr until a reload succeeded.
    EffectRenderer* renderer() { return mRenderer.get(); }
    const EffectRenderer* renderer() const { return mRenderer.get(); }

    const std::string& path() const { return mPath; }
    // Diagnostics of the last reload (warnings of a good one, errors of a failed one).
    const std::vector<fx::Diagnostic>& diagnostics() const { return mDiagnostics.items(); }
    bool lastReloadFailed() const { return mLastFailed; }
    // The last reload's errors, one "file:line:column: error: message" per line ("" if it succeeded).
    std::string errorText() const;
    // Successful loads so far: changes whenever renderer() is a new object.
    size_t generation() const { return mGeneration; }
    const ReloadStats& lastStats() const { return mStats; }
    const std::vector<std::string>& watchedFiles() const { return mWatchedFiles; }

    fx::CompileCache& cache() { return mCache; }

private:
    void carryOverPinnedParameters(const EffectRenderer& from, EffectRenderer& to);

    std::string mPath;
    fx::ParseOptions mParseOptions;
    std::shared_ptr<EffectPool> mPool;
    fx::CompileCache mCache;
    FileWatcher mWatcher;
    std::vector<std::string> mWatchedFiles;
    std::unique_ptr<EffectRenderer> mRenderer;
    fx::DiagnosticList mDiagnostics;
    bool mLastFailed = false;
    size_t mGeneration = 0;
    ReloadStats mStats;
};

}  // namespace runtime
