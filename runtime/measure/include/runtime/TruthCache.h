// TruthCache: ray-cast ground truths (GroundTruth.h) kept in a folder, one file per truth, so that a scene's
// truth is cast once and read back by every later bench, shard, check or stress run that needs it
// (`--truth-cache DIR`). Casting is the slow part of measuring a scene (seconds to minutes for area lights);
// reading a file of one float per pixel is not.
//
// An entry is found by a key over everything the truth depends on (truthKey): the loaded scene's shadow
// casters (every triangle in world space, so a scene file, the mesh files it names, the built-in scene's
// code and any command-line change to its lights are all covered by what they produce), the light, the
// scene bounds the rays' offsets scale with, the options, the ground truth's version, and the G-buffer the
// rays start from (resolution, camera and the rasterizer's exact pixels; rendering it is cheap). A file
// whose format or truth version is not this build's, whose key, size or checksum does not match, is
// rejected with the reason and cast again, never used. Files are written under a temporary name and
// renamed, so shards sharing a folder (a network file system included) never read a half-written entry.
// GL-free: the G-buffer is data here.
#pragma once

#include <runtime/GBuffer.h>
#include <runtime/GroundTruth.h>
#include <runtime/Scene.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace runtime {

// The cache key of the truth of `light` over `gbuffer` in `scene` with `options`.
uint64_t truthKey(const Scene& scene, const Light& light, const GBuffer& gbuffer,
                  const GroundTruthOptions& options);

class TruthCache {
public:
    explicit TruthCache(std::filesystem::path directory) : mDirectory(std::move(directory)) {}

    struct Lookup {
        std::optional<GroundTruth> truth;  // the entry, when present and intact
        std::string rejected;              // why an entry that was there cannot be used; empty otherwise
    };
    // The entry for `key`, checked against the format, the truth version, the key, the `width` x `height`
    // it must have and its checksum.
    Lookup load(uint64_t key, int width, int height) const;
    // Stores `truth` as the entry for `key` (creating the folder). False with `error` set on failure.
    bool store(uint64_t key, const GroundTruth& truth, std::string& error) const;

    std::filesystem::path entryPath(uint64_t key) const;
    const std::filesystem::path& directory() const { return mDirectory; }

private:
    std::filesystem::path mDirectory;
};

}  // namespace runtime
