// GroundTruth: shadow rays through the ray-cast module (RayCastModule.h: Embree's rtcOccluded1 for hard
// shadows, rtcOccluded16 packets of 16 light samples for area lights), rows of the image split across
// threads. The module is opened when the first caster is made, so only programs that cast truth load Embree.
#include <runtime/GroundTruth.h>
#include <runtime/RuntimeModules.h>

#include <private/runtime/RayCastModule.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

namespace runtime {

namespace {

// Opened with the first caster, and kept: a failed open is tried again by the next one.
const RayCastModule& rayCastModule() {
    static const RayCastModule* module = reinterpret_cast<RayCastModuleEntry>(
        openModuleEntry("raycast", "ground-truth ray casting (Embree)", kRayCastModuleEntry))();
    return *module;
}

}  // namespace

struct ShadowRayCaster::Impl {
    const RayCastModule& module = rayCastModule();
    RayCastBvh* bvh = nullptr;
    float sceneRadius = 1.0f;
    glm::vec3 sceneCenter{0.0f};

    ~Impl() {
        if (bvh) module.release(bvh);
    }
};

ShadowRayCaster::ShadowRayCaster(const Scene& scene) : mImpl(std::make_unique<Impl>()) {
    const Bounds bounds = scene.bounds();
    mImpl->sceneRadius = std::max(bounds.radius(), 1e-3f);
    mImpl->sceneCenter = bounds.center();

    std::vector<std::vector<glm::vec3>> worldPositions;
    std::vector<CasterTriangles> objects;
    for (const SceneObject& object : scene.objects) {
        if (!object.castsShadow || !object.mesh || object.mesh->triangleCount() == 0) continue;
        const Mesh& mesh = *object.mesh;
        std::vector<glm::vec3>& world = worldPositions.emplace_back();
        world.reserve(mesh.positions.size());
        for (const glm::vec3& p : mesh.positions)
            world.push_back(glm::vec3(object.world * glm::vec4(p, 1.0f)));
        objects.push_back({world.data(), world.size(), mesh.indices.data(), mesh.triangleCount()});
    }
    std::string error;
    mImpl->bvh = mImpl->module.build(objects.data(), objects.size(), error);
    if (!mImpl->bvh) throw std::runtime_error(error);
}

ShadowRayCaster::~ShadowRayCaster() = default;

bool ShadowRayCaster::occluded(const glm::vec3& from, const glm::vec3& dir, float tMax) const {
    return mImpl->module.occluded(mImpl->bvh, ShadowRay{from, dir, tMax});
}

namespace {

// Shirley & Chiu's concentric map from the unit square to the unit disk: it keeps the strata of a
// stratified square sample set equal-area and compact on the disk.
glm::vec2 concentricDisk(float u, float v) {
    const float a = 2.0f * u - 1.0f, b = 2.0f * v - 1.0f;
    if (a == 0.0f && b == 0.0f) return glm::vec2(0.0f);
    constexpr float kQuarterPi = 0.78539816339f;
    if (std::abs(a) > std::abs(b))
        return a * glm::vec2(std::cos(kQuarterPi * b / a), std::sin(kQuarterPi * b / a));
    return b * glm::vec2(std::sin(kQuarterPi * a / b), std::cos(kQuarterPi * a / b));
}

// A per-pixel random stream (PCG-style hash of the pixel index): deterministic whatever the thread split.
struct PixelRandom {
    uint32_t state;
    explicit PixelRandom(uint64_t pixel) : state(static_cast<uint32_t>(pixel * 747796405u + 2891336453u)) {}
    float next() {
        state = state * 747796405u + 2891336453u;
        uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
        word = (word >> 22u) ^ word;
        return static_cast<float>(word >> 8) * (1.0f / 16777216.0f);
    }
};

void orthonormalBasis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
    t = std::abs(n.x) > 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    t = glm::normalize(glm::cross(t, n));
    b = glm::cross(n, t);
}

}  // namespace

GroundTruth ShadowRayCaster::compute(const GBuffer& gbuffer, const Light& light,
                                     const GroundTruthOptions& options) const {
    GroundTruth truth;
    truth.width = gbuffer.width;
    truth.height = gbuffer.height;
    truth.visibility.assign(gbuffer.pixelCount(), -1.0f);
    truth.soft = light.areaRadius > 0.0f;
    const int strata =
        truth.soft ? std::max(1, static_cast<int>(std::lround(std::sqrt(std::max(1, options.areaSamples)))))
                   : 1;
    truth.samplesPerPixel = strata * strata;

    const float offset = options.normalOffset * mImpl->sceneRadius;
    const bool directional = light.type == Light::Type::Directional;
    const glm::vec3 lightDir = glm::dot(light.direction, light.direction) > 0.0f
                                   ? glm::normalize(light.direction)
                                   : glm::vec3(0, -1, 0);
    // A directional light has no position; its area disk sits where the runtime places its view (two scene
    // radii behind the scene's centre, Light::view), so areaRadius means the same size for every light type.
    const float directionalDistance = 2.0f * mImpl->sceneRadius + glm::length(mImpl->sceneCenter);
    // "Infinitely" far for directional rays: beyond anything in the scene from any receiver.
    const float farT = 4.0f * mImpl->sceneRadius + 2.0f * glm::length(mImpl->sceneCenter) + 1.0f;

    std::atomic<int> nextRow{0};
    std::atomic<uint64_t> rays{0};
    auto worker = [&] {
        uint64_t localRays = 0;
        for (int y = nextRow++; y < gbuffer.height; y = nextRow++) {
            for (int x = 0; x < gbuffer.width; ++x) {
                const size_t i = gbuffer.index(x, y);
                if (!gbuffer.covered(i)) continue;
                const glm::vec3 p = gbuffer.position[i];
                glm::vec3 n = gbuffer.normal[i];
                const glm::vec3 toLightCentre = directional ? -lightDir : glm::normalize(light.position - p);
                // Offset towards the light's side of the surface: a receiver facing away still gets a
                // well-defined answer (its own back face would shadow it otherwise, by chance).
                if (glm::dot(n, toLightCentre) < 0.0f) n = -n;
                const glm::vec3 origin = p + n * offset;
                if (!truth.soft) {
                    const glm::vec3 dir = directional ? -lightDir : light.position - origin;
                    const float tMax = directional ? farT : 1.0f - 1e-5f;
                    truth.visibility[i] = occluded(origin, dir, tMax) ? 0.0f : 1.0f;
                    ++localRays;
                    continue;
                }
                // Area light: a disk of radius areaRadius centred on the light, facing the receiver.
                const glm::vec3 centre =
                    directional ? origin - lightDir * directionalDistance : light.position;
                const glm::vec3 axis = glm::normalize(centre - origin);
                glm::vec3 tangent, bitangent;
                orthonormalBasis(axis, tangent, bitangent);
                PixelRandom random(i);
                int visible = 0;
                ShadowRay packet[16];
                bool hit[16];
                int lane = 0;
                auto flush = [&](int lanes) {
                    mImpl->module.occluded16(mImpl->bvh, packet, lanes, hit);
                    for (int k = 0; k < lanes; ++k) visible += !hit[k];
                    localRays += static_cast<uint64_t>(lanes);
                };
                for (int sy = 0; sy < strata; ++sy) {
                    for (int sx = 0; sx < strata; ++sx) {
                        const glm::vec2 d =
                            concentricDisk((sx + random.next()) / strata, (sy + random.next()) / strata);
                        const glm::vec3 target =
                            centre + light.areaRadius * (d.x * tangent + d.y * bitangent);
                        packet[lane] = ShadowRay{origin, target - origin, 1.0f - 1e-5f};
                        if (++lane == 16) {
                            flush(16);
                            lane = 0;
                        }
                    }
                }
                if (lane > 0) flush(lane);
                truth.visibility[i] = static_cast<float>(visible) / static_cast<float>(truth.samplesPerPixel);
            }
        }
        rays += localRays;
    };
    const unsigned threadCount = options.threads > 0 ? static_cast<unsigned>(options.threads)
                                                     : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::thread> threads;
    for (unsigned t = 1; t < threadCount; ++t) threads.emplace_back(worker);
    worker();
    for (std::thread& thread : threads) thread.join();
    truth.raysCast = rays;
    return truth;
}

}  // namespace runtime
