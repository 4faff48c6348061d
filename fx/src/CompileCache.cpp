// CompileCache: see CompileCache.h.
#include <fx/CompileCache.h>

namespace fx {

namespace {
constexpr uint64_t kFnvOffset = 1469598103934665603ull;
constexpr uint64_t kFnvPrime = 1099511628211ull;

uint64_t fnv1a(uint64_t h, std::string_view text) {
    for (unsigned char c : text) {
        h ^= c;
        h *= kFnvPrime;
    }
    // A separator byte that cannot occur in text, so part boundaries matter.
    h ^= 0xffu;
    h *= kFnvPrime;
    return h;
}
}  // namespace

uint64_t CompileCache::hash(std::string_view hlsl, ShaderStage stage, std::string_view options) {
    uint64_t h = fnv1a(kFnvOffset, hlsl);
    h = fnv1a(h, stage == ShaderStage::Vertex     ? "vertex"
                 : stage == ShaderStage::Fragment ? "fragment"
                 : stage == ShaderStage::Geometry ? "geometry"
                 : stage == ShaderStage::Hull     ? "hull"
                                                  : "domain");
    return fnv1a(h, options);
}

const StageProgram* CompileCache::find(uint64_t key) {
    auto it = mEntries.find(key);
    if (it == mEntries.end()) {
        ++mMisses;
        return nullptr;
    }
    ++mHits;
    return &it->second;
}

void CompileCache::store(uint64_t key, const StageProgram& program) {
    mEntries[key] = program;
}

}  // namespace fx
