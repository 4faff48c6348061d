// TextureFile: DirectDraw Surface files, the texture format of FX Composer's and the DirectX SDK's
// effects: 2D, cube and volume textures and Direct3D 10's arrays (a DX10 header, 1D, 2D or cube
// elements), in D3D9's mask, FourCC and float formats and the DXGI colour formats with BC1-5, with their
// mip chains, handed over as RGBA floats. Read here with libsquish decoding DXT blocks: no image library's
// dependency tree comes with the runtime (docs/fxcomposer.md, "What is supported",
// lists the formats under Textures).
#pragma once

#include <fx/Diagnostics.h>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace runtime {

struct TextureFile {
    enum class Kind { Flat, Cube, Volume };
    Kind kind = Kind::Flat;
    int width = 0;  // of level 0 (a cube face's side)
    int height = 0;
    int depth = 1;     // volume slices
    int elements = 1;  // a DX10-header array's elements (arraySize; cubes of a cube array)
    // RGBA floats per mip level, top row first: Flat width x height; Volume every slice in turn; Cube the
    // six faces in turn (+X -X +Y -Y +Z -Z); an array each element in turn.
    std::vector<std::vector<float>> levels;
};

// Why a file could not be read: the diagnostic to report at the effect's texture, whose first argument is
// the file as the effect names it and whose others are `values` (a format number, a size, ...).
struct TextureFileFault {
    fx::DiagId id;
    std::vector<std::string> values;
};

// Whether the runtime reads `path` through loadTextureFile (by its extension, any case).
bool isTextureFile(const std::string& path);

// Reads every level. nullopt, with `fault` set, if the file cannot be read.
std::optional<TextureFile> loadTextureFile(const std::string& path, std::optional<TextureFileFault>& fault);

// The same from a DDS file's bytes (fuzz/fuzz_dds_file.cpp feeds it any bytes).
std::optional<TextureFile> decodeTextureFile(std::span<const uint8_t> bytes,
                                             std::optional<TextureFileFault>& fault);

}  // namespace runtime
