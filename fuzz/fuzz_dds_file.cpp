// Fuzz target 6: the DDS texture reader (runtime::decodeTextureFile), which reads files an effect names:
// any bytes must give a texture whose levels hold exactly the texels its header describes, or an error.
#include <runtime/TextureFile.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::optional<runtime::TextureFileFault> fault;
    const std::optional<runtime::TextureFile> file = runtime::decodeTextureFile({data, size}, fault);
    if (file.has_value() == fault.has_value()) __builtin_trap();
    if (!file) return 0;
    const size_t layers = size_t(file->elements) * (file->kind == runtime::TextureFile::Kind::Cube ? 6 : 1);
    for (size_t level = 0; level < file->levels.size(); ++level) {
        const size_t texels = size_t(std::max(file->width >> level, 1)) *
                              size_t(std::max(file->height >> level, 1)) *
                              size_t(std::max(file->depth >> level, 1));
        if (file->levels[level].size() != texels * layers * 4) __builtin_trap();
    }
    return 0;
}
