// EmbreeRayCaster: libshadowfx_raycast.so, the only code that links Embree 3 (RayCastModule.h): rtcOccluded1
// for single rays, rtcOccluded16 for packets.
#include <private/runtime/RayCastModule.h>

#include <embree3/rtcore.h>

#include <algorithm>

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
            vertices[3 * i + 0] = object.positions[i].x;
            vertices[3 * i + 1] = object.positions[i].y;
            vertices[3 * i + 2] = object.positions[i].z;
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

void occluded16(const RayCastBvh* bvh, const ShadowRay* rays, int count, bool* hit) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    alignas(64) RTCRay16 packet;
    alignas(64) int valid[16];
    for (int k = 0; k < 16; ++k) {
        valid[k] = k < count ? -1 : 0;
        if (k >= count) continue;
        packet.org_x[k] = rays[k].origin.x;
        packet.org_y[k] = rays[k].origin.y;
        packet.org_z[k] = rays[k].origin.z;
        packet.dir_x[k] = rays[k].direction.x;
        packet.dir_y[k] = rays[k].direction.y;
        packet.dir_z[k] = rays[k].direction.z;
        packet.tnear[k] = 0.0f;
        packet.tfar[k] = rays[k].tMax;
        packet.time[k] = 0.0f;
        packet.mask[k] = 0xFFFFFFFFu;
        packet.id[k] = static_cast<unsigned>(k);
        packet.flags[k] = 0;
    }
    rtcOccluded16(valid, bvh->scene, &context, &packet);
    for (int k = 0; k < count; ++k) hit[k] = packet.tfar[k] < 0.0f;
}

constexpr RayCastModule kModule{build, release, occluded, occluded16};

}  // namespace

}  // namespace runtime

extern "C" __attribute__((visibility("default"))) const runtime::RayCastModule* shadowfx_raycast_v1() {
    return &runtime::kModule;
}
