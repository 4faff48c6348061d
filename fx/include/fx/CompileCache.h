// CompileCache: compiled stages (GLSL + reflection) by the 64-bit hash of their generated HLSL, stage and
// compiler options. Shared across compiles of an effect (hot reload): a pass whose generated source did
// not change is not recompiled. Not thread-safe.
#pragma once

#include <fx/CompiledEffect.h>

#include <cstdint>
#include <string_view>
#include <unordered_map>

namespace fx {

class CompileCache {
public:
    // FNV-1a 64 over the parts, with a separator so that ("ab","c") and ("a","bc") differ.
    static uint64_t hash(std::string_view hlsl, ShaderStage stage, std::string_view options);

    // The cached stage for `key`, or nullptr; counts a hit or a miss.
    const StageProgram* find(uint64_t key);
    void store(uint64_t key, const StageProgram& program);

    size_t hits() const { return mHits; }
    size_t misses() const { return mMisses; }
    size_t size() const { return mEntries.size(); }
    void resetCounters() { mHits = mMisses = 0; }
    void clear() {
        mEntries.clear();
        resetCounters();
    }

private:
    std::unordered_map<uint64_t, StageProgram> mEntries;
    size_t mHits = 0;
    size_t mMisses = 0;
};

}  // namespace fx
