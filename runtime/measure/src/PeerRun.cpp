// PeerRun: see PeerRun.h.
#include <runtime/PeerRun.h>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace runtime {

namespace {

// One argument for /bin/sh: single-quoted, a quote inside closed, escaped and reopened.
std::string shellQuoted(const std::string& text) {
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

// Letters, digits, - and _ kept, anything else _ (GoldenImages.h's safeName also keeps .).
std::string peerFileName(std::string text) {
    for (char& c : text)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
    return text;
}

// A binary PGM (P5, 8 bits) as the peer writes it: values / 255, rows top to bottom.
bool readPgm(const std::filesystem::path& path, int& width, int& height, std::vector<float>& values) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    int maxValue = 0;
    in >> magic >> width >> height >> maxValue;
    in.get();  // the one whitespace byte before the pixels
    if (!in || magic != "P5" || maxValue != 255 || width <= 0 || height <= 0) return false;
    std::vector<unsigned char> bytes(static_cast<size_t>(width) * static_cast<size_t>(height));
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!in) return false;
    values.resize(bytes.size());
    for (size_t i = 0; i < bytes.size(); ++i) values[i] = bytes[i] / 255.0f;
    return true;
}

}  // namespace

std::vector<std::string> peerTechniques(const std::string& program) {
    std::vector<std::string> names;
    FILE* pipe = popen((shellQuoted(program) + " --technique list 2>/dev/null").c_str(), "r");
    if (!pipe) return names;
    char line[256];
    while (std::fgets(line, sizeof line, pipe)) {
        std::string name(line);
        while (!name.empty() && (name.back() == '\n' || name.back() == '\r')) name.pop_back();
        if (!name.empty()) names.push_back(name);
    }
    if (pclose(pipe) != 0) names.clear();
    return names;
}

namespace {

// Runs the peer with `sceneArguments` (its --scene or --stress-case), `label` naming the scene in file
// names and errors; its frame must be `height` rows of the request's width.
std::optional<PeerResult> runPeerProgram(const PeerRequest& request, const std::string& sceneArguments,
                                         const std::string& label, int height,
                                         const std::filesystem::path& workDir, std::string& error) {
    const std::string base =
        peerFileName(request.technique + "_" + label + "_" + std::to_string(request.mapSize));
    const std::filesystem::path frame = workDir / (base + ".pgm");
    const std::filesystem::path json = workDir / (base + ".json");
    const std::filesystem::path log = workDir / (base + ".log");
    std::ostringstream command;
    command << shellQuoted(request.program) << sceneArguments << " --technique "
            << shellQuoted(request.technique) << " --map-size " << request.mapSize << " --width "
            << request.width << " --height " << request.height << " --frames " << request.frames
            << " --warmup " << request.warmup << " --out-visibility " << shellQuoted(frame.string())
            << " --out-json " << shellQuoted(json.string()) << " >" << shellQuoted(log.string()) << " 2>&1";
    if (std::system(command.str().c_str()) != 0) {
        std::ifstream in(log);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        error = request.program + " failed on " + label + " (" + request.technique + "): " + text;
        return std::nullopt;
    }
    PeerResult result;
    int frameWidth = 0, frameHeight = 0;
    if (!readPgm(frame, frameWidth, frameHeight, result.visibility)) {
        error = "cannot read the peer's frame " + frame.string();
        return std::nullopt;
    }
    if (frameWidth != request.width || frameHeight != height) {
        error = "the peer's frame is " + std::to_string(frameWidth) + "x" + std::to_string(frameHeight) +
                ", the G-buffer's " + std::to_string(request.width) + "x" + std::to_string(height);
        return std::nullopt;
    }
    std::filesystem::remove(frame);
    try {
        std::ifstream in(json);
        const nlohmann::json record = nlohmann::json::parse(in);
        result.frameMs = record.at("frame_ms").get<std::vector<double>>();
        result.glRenderer = record.at("gl_renderer").get<std::string>();
        result.libraryVersion = record.value("osg_version", "");
        result.mapSizeHonoured = record.at("map_size_honoured").get<bool>();
    } catch (const std::exception& e) {
        error = "cannot read the peer's record " + json.string() + ": " + e.what();
        return std::nullopt;
    }
    if (result.frameMs.empty()) {
        error = "the peer timed no frames";
        return std::nullopt;
    }
    return result;
}

}  // namespace

std::optional<PeerResult> runPeer(const PeerRequest& request, const SceneTruth& truth,
                                  const std::filesystem::path& workDir, std::string& error) {
    std::string arguments = " --scene " + shellQuoted(request.scene);
    if (truth.light && truth.light->type == Light::Type::Directional) {
        char direction[96];
        std::snprintf(direction, sizeof direction, "%.9g,%.9g,%.9g", truth.light->direction.x,
                      truth.light->direction.y, truth.light->direction.z);
        arguments += std::string(" --light-direction ") + direction;
    }
    if (request.width != truth.gbuffer.width || request.height != truth.gbuffer.height) {
        error = "the peer was asked for " + std::to_string(request.width) + "x" +
                std::to_string(request.height) + ", the G-buffer is " + std::to_string(truth.gbuffer.width) +
                "x" + std::to_string(truth.gbuffer.height);
        return std::nullopt;
    }
    return runPeerProgram(request, arguments, truth.scene.name, request.height, workDir, error);
}

std::optional<std::vector<std::vector<float>>> runPeerOnStressCase(const PeerRequest& request, size_t cameras,
                                                                   const std::filesystem::path& workDir,
                                                                   std::string& error) {
    const std::optional<PeerResult> result =
        runPeerProgram(request, " --stress-case " + shellQuoted(request.scene), request.scene,
                       request.height * static_cast<int>(cameras), workDir, error);
    if (!result) return std::nullopt;
    const size_t pixels = static_cast<size_t>(request.width) * static_cast<size_t>(request.height);
    std::vector<std::vector<float>> frames;
    for (size_t view = 0; view < cameras; ++view)
        frames.emplace_back(result->visibility.begin() + static_cast<std::ptrdiff_t>(view * pixels),
                            result->visibility.begin() + static_cast<std::ptrdiff_t>((view + 1) * pixels));
    return frames;
}

}  // namespace runtime
