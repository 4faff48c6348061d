// GoldenImages: where a technique's golden image for a renderer lives, and where `check --update` writes it.
//
// EFFECT_DIR/golden/EFFECT/renderer.txt names the renderer key the plain goldens were made with (its first
// line; the second records the full GL_RENDERER string). A technique's goldens are
// golden/EFFECT/TECHNIQUE/SCENE.png for that renderer and SCENE.KEY.png for any other renderer KEY; a
// renderer with neither is NOT_SUPPORTED (FAIL with --require-goldens). The key is the first word of
// GL_RENDERER in lower case ("llvmpipe (LLVM 15.0.6, 256 bits)" -> llvmpipe): OSMesa and EGL on Mesa's
// llvmpipe share one set.
#pragma once

#include <filesystem>
#include <string>

namespace runtime {

// "llvmpipe (LLVM 15.0.6, 256 bits)" -> "llvmpipe"; "unknown" if it has no word.
std::string rendererKey(const std::string& glRenderer);

// `text` as one file or folder name: every character but letters, digits, '-', '_' and '.' replaced by '_'.
std::string safeName(std::string text);

struct GoldenPlace {
    std::filesystem::path path;   // where the golden is or would be
    bool forThisRenderer = true;  // false: the renderer has no goldens (NOT_SUPPORTED)
    std::string note;             // why not
};

// Where the golden of `technique` on `scene` for renderer `key` is, under the effect's golden folder.
GoldenPlace findGolden(const std::filesystem::path& effectGoldens, const std::string& technique,
                       const std::string& scene, const std::string& key);

// Where --update writes: the plain name for the reference renderer (the first to write, recorded in
// renderer.txt), SCENE.KEY.png for any other.
std::filesystem::path goldenToWrite(const std::filesystem::path& effectGoldens, const std::string& technique,
                                    const std::string& scene, const std::string& key,
                                    const std::string& glRenderer);

}  // namespace runtime
