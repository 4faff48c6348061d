// EmbreeRayCaster: libshadowfx_raycast.so, the only code that links Embree 3 (RayCastModule.h): the BVH, and
// the ground truth's whole loop over the G-buffer (rtcOccluded1 for hard shadows, rtcOccluded16 packets of
// 16 light samples for area lights, rows of the image split across threads), so that no ray crosses the
// module's boundary on its own.
#include <private/runtime/RayCastModule.h>

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

struct runtime::RayCastBvh {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;

    ~RayCastBvh() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

namespace runtime {

namespace {

RayCastBvh* build(const CasterTriangles* objects, size_t objectCount, std::string& error) {
    auto* bvh = new RayCastBvh;
    bvh->device = rtcNewDevice(nullptr);
    if (!bvh->device) {
        delete bvh;
        error = "Embree: rtcNewDevice failed";
        return nullptr;
    }
    bvh->scene = rtcNewScene(bvh->device);
    // Shadow rays want exactness, not build speed: the high-quality BVH and robust (watertight) traversal,
    // so a ray through a shared edge of two triangles cannot slip between them.
    rtcSetSceneBuildQuality(bvh->scene, RTC_BUILD_QUALITY_HIGH);
    rtcSetSceneFlags(bvh->scene, RTC_SCENE_FLAG_ROBUST);
    for (size_t o = 0; o < objectCount; ++o) {
        const CasterTriangles& object = objects[o];
        RTCGeometry geometry = rtcNewGeometry(bvh->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), object.positionCount));
        for (size_t i = 0; i < object.positionCount; ++i) {
            const glm::vec3 w = glm::vec3(object.world * glm::vec4(object.positions[i], 1.0f));
            vertices[3 * i + 0] = w.x;
            vertices[3 * i + 1] = w.y;
            vertices[3 * i + 2] = w.z;
        }
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
                                                                       RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                                       object.triangleCount));
        std::copy(object.indices, object.indices + 3 * object.triangleCount, indices);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(bvh->scene, geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(bvh->scene);
    return bvh;
}

void release(RayCastBvh* bvh) {
    delete bvh;
}

bool occluded(const RayCastBvh* bvh, const ShadowRay& shadowRay) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = shadowRay.origin.x;
    ray.org_y = shadowRay.origin.y;
    ray.org_z = shadowRay.origin.z;
    ray.dir_x = shadowRay.direction.x;
    ray.dir_y = shadowRay.direction.y;
    ray.dir_z = shadowRay.direction.z;
    ray.tnear = 0.0f;
    ray.tfar = shadowRay.tMax;
    ray.mask = 0xFFFFFFFFu;
    rtcOccluded1(bvh->scene, &context, &ray);
    return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

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

// Where a receiver's rays start: `height` off its plane (clear of the plane's float error), reached along
// the ray towards the light's centre, so that the ray is the one from the receiver itself and a shadow's
// edge stays where the caster puts it. Lifting the start along the normal instead would move every edge
// by height / tan(elevation) into the shadow (scenes/sun_street.json, the sun 22 degrees up: 1e-4 of the
// scene's radius, 5.7 mm, moves the ground's edges 1.4 cm, and a map's exact edge scored a line of false
// shadow along each of them at every map size). Where the light grazes the surface the walk along the ray
// would grow without bound and step over nearby occluders, so it stops at height / kAlongRayMinCosine and
// the normal makes up the rest of the height.
constexpr float kAlongRayMinCosine = 0.1f;

glm::vec3 rayOrigin(const glm::vec3& p, const glm::vec3& n, const glm::vec3& toLight, float height) {
    const float cosine = glm::dot(n, toLight);
    const float along = height / std::max(cosine, kAlongRayMinCosine);
    return p + toLight * along + n * (height - along * cosine);
}

GroundTruth compute(const RayCastBvh* bvh, const GBuffer& gbuffer, const Light& light,
                    const GroundTruthOptions& options, float sceneRadius, const glm::vec3& sceneCenter) {
    GroundTruth truth;
    truth.width = gbuffer.width;
    truth.height = gbuffer.height;
    truth.visibility.assign(gbuffer.pixelCount(), -1.0f);
    truth.soft = light.areaRadius > 0.0f;
    const int strata =
        truth.soft ? std::max(1, static_cast<int>(std::lround(std::sqrt(std::max(1, options.areaSamples)))))
                   : 1;
    truth.samplesPerPixel = strata * strata;

    const float offset = options.normalOffset * sceneRadius;
    const bool directional = light.type == Light::Type::Directional;
    const glm::vec3 lightDir = glm::dot(light.direction, light.direction) > 0.0f
                                   ? glm::normalize(light.direction)
                                   : glm::vec3(0, -1, 0);
    // A directional light has no position; its area disk sits where the runtime places its view (two scene
    // radii behind the scene's centre, Light::view), so areaRadius means the same size for every light type.
    const float directionalDistance = 2.0f * sceneRadius + glm::length(sceneCenter);
    // "Infinitely" far for directional rays: beyond anything in the scene from any receiver.
    const float farT = 4.0f * sceneRadius + 2.0f * glm::length(sceneCenter) + 1.0f;

    std::atomic<int> nextRow{0};
    std::atomic<uint64_t> rays{0};
    auto worker = [&] {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
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
                const glm::vec3 origin = rayOrigin(p, n, toLightCentre, offset);
                if (!truth.soft) {
                    const glm::vec3 dir = directional ? -lightDir : light.position - origin;
                    const float tMax = directional ? farT : 1.0f - 1e-5f;
                    truth.visibility[i] = occluded(bvh, ShadowRay{origin, dir, tMax}) ? 0.0f : 1.0f;
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
                alignas(64) RTCRay16 packet;
                alignas(64) int valid[16];
                int lane = 0;
                auto flush = [&](int lanes) {
                    for (int k = 0; k < 16; ++k) valid[k] = k < lanes ? -1 : 0;
                    rtcOccluded16(valid, bvh->scene, &context, &packet);
                    for (int k = 0; k < lanes; ++k) visible += packet.tfar[k] >= 0.0f;
                    localRays += static_cast<uint64_t>(lanes);
                };
                for (int sy = 0; sy < strata; ++sy) {
                    for (int sx = 0; sx < strata; ++sx) {
                        const glm::vec2 d =
                            concentricDisk((sx + random.next()) / strata, (sy + random.next()) / strata);
                        const glm::vec3 target =
                            centre + light.areaRadius * (d.x * tangent + d.y * bitangent);
                        const glm::vec3 dir = target - origin;
                        packet.org_x[lane] = origin.x;
                        packet.org_y[lane] = origin.y;
                        packet.org_z[lane] = origin.z;
                        packet.dir_x[lane] = dir.x;
                        packet.dir_y[lane] = dir.y;
                        packet.dir_z[lane] = dir.z;
                        packet.tnear[lane] = 0.0f;
                        packet.tfar[lane] = 1.0f - 1e-5f;
                        packet.time[lane] = 0.0f;
                        packet.mask[lane] = 0xFFFFFFFFu;
                        packet.id[lane] = static_cast<unsigned>(lane);
                        packet.flags[lane] = 0;
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

constexpr RayCastModule kModule{build, release, occluded, compute};

}  // namespace

}  // namespace runtime

extern "C" __attribute__((visibility("default"))) const runtime::RayCastModule* shadowfx_raycast_v1() {
    return &runtime::kModule;
}
