// TextureFile: DirectDraw Surface files, the texture format of FX Composer's and the DirectX SDK's
// effects (2D, cube and volume textures; uncompressed or DXT1/3/5; mip chains), read through
// OpenImageIO and handed over as RGBA floats. Direct3D 10's arrays (a DX10 header with arraySize > 1, 2D,
// 1D or cube elements) are read here, since OpenImageIO 2.4 reads their first element only; uncompressed
// formats only.
#pragma once

#include <optional>
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
    // six faces in turn (+X -X +Y -Y +Z -Z); an array each element in turn. Cube maps that are not arrays
    // carry level 0 only: OpenImageIO 2.4 misreads the smaller levels of DDS cube maps, so the runtime
    // regenerates them.
    std::vector<std::vector<float>> levels;
};

// Whether the runtime reads `path` through loadTextureFile (by its extension, any case).
bool isTextureFile(const std::string& path);

// Reads every level. nullopt, with `error` set, if the file cannot be read.
std::optional<TextureFile> loadTextureFile(const std::string& path, std::string& error);

}  // namespace runtime
