// TruthCache: see TruthCache.h.
//
// An entry file, little-endian as written by this build:
//   "SFXTRUTH"  u32 format  u32 truth version  u64 key  i32 width  i32 height  i32 samples per pixel
//   u32 soft  u64 rays  u64 pixel count  f32 visibility[pixel count]  u64 checksum of everything before
#include <runtime/TruthCache.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <unistd.h>
#include <vector>

namespace runtime {

namespace {

constexpr char kMagic[8] = {'S', 'F', 'X', 'T', 'R', 'U', 'T', 'H'};
constexpr uint32_t kFormatVersion = 1;
constexpr size_t kHeaderBytes = 8 + 4 + 4 + 8 + 4 + 4 + 4 + 4 + 8 + 8;

// FNV-1a, 64 bits, fed piece by piece: a key over mixed data, and the entry's checksum. A cache key, not a
// defence against a crafted file: a chance collision among the truths of one folder is ~n^2 / 2^65.
class Fnv1a {
public:
    void bytes(const void* data, size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) {
            mHash ^= p[i];
            mHash *= 1099511628211ull;
        }
    }
    template <typename T>
    void value(const T& v) {
        bytes(&v, sizeof v);
    }
    template <typename T>
    void values(const std::vector<T>& v) {
        value(static_cast<uint64_t>(v.size()));
        bytes(v.data(), v.size() * sizeof(T));
    }
    uint64_t digest() const { return mHash; }

private:
    uint64_t mHash = 1469598103934665603ull;
};

class Writer {
public:
    template <typename T>
    void value(const T& v) {
        const auto* p = reinterpret_cast<const char*>(&v);
        mBytes.insert(mBytes.end(), p, p + sizeof v);
    }
    std::vector<char> mBytes;
};

class Reader {
public:
    explicit Reader(const std::vector<char>& bytes) : mBytes(bytes) {}
    template <typename T>
    T value() {
        T v{};
        std::memcpy(&v, mBytes.data() + mOffset, sizeof v);
        mOffset += sizeof v;
        return v;
    }
    size_t offset() const { return mOffset; }

private:
    const std::vector<char>& mBytes;
    size_t mOffset = 0;
};

uint64_t checksum(const char* data, size_t size) {
    Fnv1a hash;
    hash.bytes(data, size);
    return hash.digest();
}

}  // namespace

uint64_t truthKey(const Scene& scene, const Light& light, const GBuffer& gbuffer,
                  const GroundTruthOptions& options) {
    Fnv1a hash;
    hash.value(kFormatVersion);
    hash.value(kGroundTruthVersion);
    // The casters as the ray caster sees them: world-space triangles, in object order.
    for (const SceneObject& object : scene.objects) {
        if (!object.castsShadow || !object.mesh || object.mesh->triangleCount() == 0) continue;
        hash.value(object.world);
        hash.values(object.mesh->positions);
        hash.values(object.mesh->indices);
    }
    const Bounds bounds = scene.bounds();
    hash.value(bounds.min);
    hash.value(bounds.max);
    hash.value(static_cast<int>(light.type));
    hash.value(light.position);
    hash.value(light.direction);
    hash.value(light.spotAngle);
    hash.value(light.areaRadius);
    hash.value(options.areaSamples);
    hash.value(options.normalOffset);
    // options.threads changes nothing: the per-pixel random streams do not depend on the split.
    hash.value(gbuffer.width);
    hash.value(gbuffer.height);
    hash.values(gbuffer.position);
    hash.values(gbuffer.normal);
    hash.values(gbuffer.objectId);
    return hash.digest();
}

std::filesystem::path TruthCache::entryPath(uint64_t key) const {
    char name[32];
    std::snprintf(name, sizeof name, "%016llx.truth", static_cast<unsigned long long>(key));
    return mDirectory / name;
}

TruthCache::Lookup TruthCache::load(uint64_t key, int width, int height) const {
    Lookup lookup;
    const std::filesystem::path path = entryPath(key);
    std::ifstream in(path, std::ios::binary);
    if (!in) return lookup;  // no entry yet
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto reject = [&](const std::string& why) {
        lookup.rejected = path.string() + ": " + why;
        return lookup;
    };
    if (bytes.size() < kHeaderBytes + 8 || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        return reject("not a ground-truth cache entry (truncated or foreign)");
    Reader reader(bytes);
    reader.value<std::array<char, 8>>();
    const auto format = reader.value<uint32_t>();
    const auto version = reader.value<uint32_t>();
    if (format != kFormatVersion || version != kGroundTruthVersion)
        return reject("stale entry (format " + std::to_string(format) + ", truth version " +
                      std::to_string(version) + "; this build writes " + std::to_string(kFormatVersion) +
                      ", " + std::to_string(kGroundTruthVersion) + ")");
    if (reader.value<uint64_t>() != key) return reject("holds the truth of another key");
    GroundTruth truth;
    truth.width = reader.value<int32_t>();
    truth.height = reader.value<int32_t>();
    truth.samplesPerPixel = reader.value<int32_t>();
    truth.soft = reader.value<uint32_t>() != 0;
    truth.raysCast = reader.value<uint64_t>();
    const auto pixels = reader.value<uint64_t>();
    if (truth.width != width || truth.height != height ||
        pixels != static_cast<uint64_t>(width) * static_cast<uint64_t>(height))
        return reject("holds a " + std::to_string(truth.width) + "x" + std::to_string(truth.height) +
                      " truth where " + std::to_string(width) + "x" + std::to_string(height) +
                      " was asked for");
    if (bytes.size() != kHeaderBytes + pixels * sizeof(float) + 8)
        return reject("size " + std::to_string(bytes.size()) +
                      " bytes does not match its header (truncated?)");
    const size_t payloadEnd = bytes.size() - 8;
    uint64_t stored = 0;
    std::memcpy(&stored, bytes.data() + payloadEnd, sizeof stored);
    if (stored != checksum(bytes.data(), payloadEnd)) return reject("checksum mismatch (corrupted)");
    truth.visibility.resize(pixels);
    std::memcpy(truth.visibility.data(), bytes.data() + reader.offset(), pixels * sizeof(float));
    lookup.truth = std::move(truth);
    return lookup;
}

bool TruthCache::store(uint64_t key, const GroundTruth& truth, std::string& error) const {
    std::error_code fsError;
    std::filesystem::create_directories(mDirectory, fsError);
    if (fsError) {
        error = "cannot create " + mDirectory.string() + ": " + fsError.message();
        return false;
    }
    Writer writer;
    writer.mBytes.insert(writer.mBytes.end(), kMagic, kMagic + sizeof kMagic);
    writer.value(kFormatVersion);
    writer.value(kGroundTruthVersion);
    writer.value(key);
    writer.value(static_cast<int32_t>(truth.width));
    writer.value(static_cast<int32_t>(truth.height));
    writer.value(static_cast<int32_t>(truth.samplesPerPixel));
    writer.value(static_cast<uint32_t>(truth.soft ? 1 : 0));
    writer.value(truth.raysCast);
    writer.value(static_cast<uint64_t>(truth.visibility.size()));
    const auto* pixels = reinterpret_cast<const char*>(truth.visibility.data());
    writer.mBytes.insert(writer.mBytes.end(), pixels, pixels + truth.visibility.size() * sizeof(float));
    writer.value(checksum(writer.mBytes.data(), writer.mBytes.size()));

    // Written aside and renamed into place: the rename is atomic, so a reader sees no entry or a whole one.
    const std::filesystem::path path = entryPath(key);
    const std::filesystem::path temporary = path.string() + ".tmp." + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(writer.mBytes.data(), static_cast<std::streamsize>(writer.mBytes.size()));
        if (!out) {
            error = "cannot write " + temporary.string();
            std::filesystem::remove(temporary, fsError);
            return false;
        }
    }
    std::filesystem::rename(temporary, path, fsError);
    if (fsError) {
        error = "cannot rename " + temporary.string() + " to " + path.string() + ": " + fsError.message();
        std::filesystem::remove(temporary, fsError);
        return false;
    }
    return true;
}

}  // namespace runtime
