// ReloadableEffect: parse -> compile (through the shared cache) -> create, keeping the last good renderer.
#include <runtime/ReloadableEffect.h>

#include <fx/CompiledEffectFile.h>
#include <fx/EffectCompiler.h>
#include <fx/EffectFile.h>

#include <set>
#include <sstream>

namespace runtime {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Same HLSL type: what a carried-over value must have, since Value::data is laid out by the type.
bool sameType(const fx::TypeDesc& a, const fx::TypeDesc& b) {
    return a.base == b.base && a.shape == b.shape && a.rows == b.rows && a.cols == b.cols &&
           a.arrayDims == b.arrayDims && a.structName == b.structName;
}

}  // namespace

ReloadableEffect::ReloadableEffect(std::string path, fx::ParseOptions parseOptions,
                                   std::shared_ptr<EffectPool> pool)
    : mPath(std::move(path)), mParseOptions(std::move(parseOptions)), mPool(std::move(pool)) {
    // Until a parse says which files the effect opens, watch the main file: a first load that fails
    // must still be retried when the user fixes it.
    mWatchedFiles = {mPath};
    mWatcher.setFiles(mWatchedFiles);
}

ReloadableEffect::~ReloadableEffect() = default;

bool ReloadableEffect::reload() {
    mDiagnostics.clear();
    mStats = {};
    const size_t hitsBefore = mCache.hits();
    const size_t missesBefore = mCache.misses();

    Clock::time_point start = Clock::now();
    std::shared_ptr<fx::CompiledEffect> compiled;
    std::shared_ptr<fx::Effect> effect;
    if (fx::isCompiledEffectFile(mPath)) {
        // A compiled effect file opens no include: reloading it reads it again.
        compiled = fx::readCompiledEffectFile(mPath, mDiagnostics);
        mStats.parseMs = millisecondsSince(start);
    } else {
        effect = fx::parseEffectFile(mPath, mParseOptions, mDiagnostics);
        mStats.parseMs = millisecondsSince(start);
    }
    if (effect) {
        // Watch what this parse opened, even if compiling fails below: the fix may be in an include.
        mWatchedFiles =
            effect->includedFiles.empty() ? std::vector<std::string>{mPath} : effect->includedFiles;
        mWatcher.setFiles(mWatchedFiles);
    }

    if (effect && !mDiagnostics.hasErrors()) {
        fx::CompileOptions options;
        options.cache = &mCache;  // all techniques: the viewer switches between them without a reload
        start = Clock::now();
        compiled = fx::compileEffect(effect, options, mDiagnostics);
        if (compiled) compiled->provenance = fx::effectProvenance(mPath, mParseOptions);
        mStats.compileMs = millisecondsSince(start);
    }
    mStats.cacheHits = mCache.hits() - hitsBefore;
    mStats.cacheMisses = mCache.misses() - missesBefore;

    std::unique_ptr<EffectRenderer> created;
    if (compiled && !mDiagnostics.hasErrors()) {
        start = Clock::now();
        created = EffectRenderer::create(compiled, mDiagnostics, mPool);
        mStats.createMs = millisecondsSince(start);
    }
    if (!created || mDiagnostics.hasErrors()) {
        mLastFailed = true;  // the last good renderer keeps rendering
        return false;
    }
    if (mRenderer) carryOverPinnedParameters(*mRenderer, *created);
    // The old renderer's GL objects go now, while the caller's context is current.
    mRenderer = std::move(created);
    mLastFailed = false;
    ++mGeneration;
    return true;
}

ReloadableEffect::Result ReloadableEffect::reloadIfChanged(std::chrono::milliseconds timeout,
                                                           std::chrono::milliseconds debounce) {
    if (mWatcher.waitForChange(timeout, debounce).empty()) return Result::Unchanged;
    return reload() ? Result::Reloaded : Result::Failed;
}

std::string ReloadableEffect::errorText() const {
    if (!mLastFailed) return "";
    // glslang can report one error twice (once per stage unit that contains the function): list it once.
    std::ostringstream text;
    std::set<std::string> seen;
    for (const fx::Diagnostic& diagnostic : mDiagnostics.items()) {
        if (diagnostic.severity != fx::Severity::Error) continue;
        const std::string line = fx::renderDiagnostic(diagnostic, false);
        if (seen.insert(line).second) text << line << "\n";
    }
    return text.str();
}

void ReloadableEffect::carryOverPinnedParameters(const EffectRenderer& from, EffectRenderer& to) {
    const std::vector<fx::ParameterInfo>& oldParameters = from.effect().parameters;
    const std::vector<fx::ParameterInfo>& newParameters = to.effect().parameters;
    for (size_t i = 0; i < oldParameters.size(); ++i) {
        if (!from.isPinned(i)) continue;
        const std::optional<size_t> j = to.findParameter(oldParameters[i].name);
        if (!j || !sameType(oldParameters[i].type, newParameters[*j].type)) continue;
        // The pool holds a shared value, newer than the old renderer's where another effect set it since.
        if (mPool && newParameters[*j].isShared) continue;
        to.setParameter(*j, from.parameter(i));
    }
}

}  // namespace runtime
