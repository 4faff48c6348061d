// GoldenImages: see GoldenImages.h.
#include "GoldenImages.h"

#include <fstream>

namespace runtime {

namespace {

std::string readRendererKey(const std::filesystem::path& effectGoldens) {
    std::ifstream file(effectGoldens / "renderer.txt");
    std::string key;
    std::getline(file, key);
    key.erase(key.find_last_not_of(" \t\r") + 1);
    return key;
}

}  // namespace

std::string rendererKey(const std::string& glRenderer) {
    std::string key;
    for (char c : glRenderer) {
        if (std::isalnum(static_cast<unsigned char>(c))) {
            key += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        } else if (!key.empty()) {
            break;
        }
    }
    return key.empty() ? "unknown" : key;
}

std::string safeName(std::string text) {
    for (char& c : text)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
    return text;
}

GoldenPlace findGolden(const std::filesystem::path& effectGoldens, const std::string& technique,
                       const std::string& scene, const std::string& key) {
    const std::filesystem::path folder = effectGoldens / safeName(technique);
    GoldenPlace place;
    place.path = folder / (safeName(scene) + "." + key + ".png");
    if (std::filesystem::exists(place.path)) return place;
    const std::string referenceKey = readRendererKey(effectGoldens);
    place.path = folder / (safeName(scene) + ".png");
    if (referenceKey.empty() || referenceKey == key) return place;  // missing renderer.txt: made for us
    place.forThisRenderer = false;
    place.note = "no goldens for renderer '" + key + "' (they were made with '" + referenceKey + "')";
    return place;
}

std::filesystem::path goldenToWrite(const std::filesystem::path& effectGoldens, const std::string& technique,
                                    const std::string& scene, const std::string& key,
                                    const std::string& glRenderer) {
    std::string referenceKey = readRendererKey(effectGoldens);
    if (referenceKey.empty()) {
        std::filesystem::create_directories(effectGoldens);
        std::ofstream(effectGoldens / "renderer.txt") << key << "\n# made with: " << glRenderer << "\n";
        referenceKey = key;
    }
    const std::filesystem::path folder = effectGoldens / safeName(technique);
    std::filesystem::create_directories(folder);
    return folder / (safeName(scene) + (referenceKey == key ? "" : "." + key) + ".png");
}

}  // namespace runtime
