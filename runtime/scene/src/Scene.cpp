// Scene: camera and light matrices (D3DX conventions, see Scene.h), bounds, exact segment visibility and
// world-to-pixel projection.
#include <runtime/Scene.h>

#include <private/runtime/NameLookups.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>

namespace runtime {

namespace {

// Up vector for a view along `direction`: world +y unless that is (nearly) parallel, as for a light
// straight overhead, where lookAt would get a degenerate basis.
glm::vec3 upFor(const glm::vec3& direction) {
    return std::abs(glm::normalize(direction).y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f)
                                                         : glm::vec3(0.0f, 1.0f, 0.0f);
}

// A bounds radius that never collapses to zero, so a scene with a single point still gets a valid frustum.
float safeRadius(const Bounds& bounds) {
    return std::max(bounds.radius(), 1e-3f);
}

glm::vec3 safeDirection(const glm::vec3& direction) {
    return glm::dot(direction, direction) > 1e-12f ? glm::normalize(direction) : glm::vec3(0.0f, -1.0f, 0.0f);
}

// The world axis whose direction is furthest from `direction`: always a well-conditioned up vector.
glm::vec3 leastAlignedAxis(const glm::vec3& direction) {
    const glm::vec3 a = glm::abs(direction);
    if (a.x <= a.y && a.x <= a.z) return {1.0f, 0.0f, 0.0f};
    return a.y <= a.z ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
}

// Möller-Trumbore: the parameter t along from + t * dir of the hit with triangle (a, b, c), either side.
std::optional<float> intersect(const glm::vec3& from, const glm::vec3& dir, const glm::vec3& a,
                               const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(dir, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) return std::nullopt;  // parallel to the triangle's plane
    const float inv = 1.0f / det;
    const glm::vec3 s = from - a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f) return std::nullopt;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(dir, q) * inv;
    if (v < 0.0f || u + v > 1.0f) return std::nullopt;
    return glm::dot(e2, q) * inv;
}

// Slab test of the segment from + t * dir, t in [t0, t1], against an axis-aligned box.
bool segmentHitsBox(const glm::vec3& from, const glm::vec3& dir, float t0, float t1, const glm::vec3& lo,
                    const glm::vec3& hi) {
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(dir[axis]) < 1e-12f) {
            if (from[axis] < lo[axis] || from[axis] > hi[axis]) return false;
            continue;
        }
        float a = (lo[axis] - from[axis]) / dir[axis];
        float b = (hi[axis] - from[axis]) / dir[axis];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1) return false;
    }
    return true;
}

}  // namespace

float Bounds::radius() const {
    return glm::length(max - min) * 0.5f;
}

// The camera's own up vector unless it is (nearly) parallel to the view direction, as for a camera looking
// straight down with up = +y (stress case zenith-camera-down), where lookAt's basis would be NaN; then the
// world axis least aligned with the view direction.
glm::mat4 Camera::view() const {
    const glm::vec3 forward = safeDirection(target - position);
    const glm::vec3 usableUp =
        glm::length(glm::cross(forward, safeDirection(up))) > 1e-3f ? up : leastAlignedAxis(forward);
    return glm::lookAtLH(position, position + forward, usableUp);
}

glm::mat4 Camera::projection(float aspect) const {
    return glm::perspectiveLH_ZO(fovY, aspect, nearPlane, farPlane);
}

// Directional: the eye sits two radii back from the centre of the bounding sphere, so the sphere spans view
// depths [radius, 3 radius]; spot/point: the eye is the light itself.
glm::mat4 Light::view(const Bounds& bounds) const {
    const glm::vec3 dir = safeDirection(direction);
    if (type == Type::Directional) {
        const glm::vec3 centre = bounds.center();
        return glm::lookAtLH(centre - dir * (2.0f * safeRadius(bounds)), centre, upFor(dir));
    }
    return glm::lookAtLH(position, position + dir, upFor(dir));
}

// Near/far enclose the bounding sphere with a 1% margin so vertices on it are not clipped by rounding.
glm::mat4 Light::projection(const Bounds& bounds, float nearestDepth) const {
    const float radius = safeRadius(bounds);
    const float margin = 0.01f * radius;
    if (type == Type::Directional) {
        return glm::orthoLH_ZO(-radius, radius, -radius, radius, radius - margin, 3.0f * radius + margin);
    }
    // Spot, and point lights for now: a point light would need a cube map (six 90-degree frusta); until the
    // runtime has one, it is treated as a spot light with a 90-degree cone along `direction`.
    const float angle = type == Type::Spot ? spotAngle : glm::half_pi<float>();
    const float centreDepth = glm::dot(bounds.center() - position, safeDirection(direction));
    const float farPlane = std::max(centreDepth + radius + margin, 2.0f * margin);
    // Near as far out as the bounds allow (depth precision), but never zero or behind the light.
    const float wanted = std::max(centreDepth - radius - margin, 0.99f * nearestDepth);
    const float nearPlane = std::clamp(wanted, std::max(1e-3f * farPlane, 1e-3f), farPlane * 0.5f);
    return glm::perspectiveLH_ZO(angle, 1.0f, nearPlane, farPlane);
}

Scene Scene::translated(const glm::vec3& offset) const {
    Scene moved = *this;
    const glm::mat4 move = glm::translate(glm::mat4(1.0f), offset);
    for (SceneObject& object : moved.objects) object.world = move * object.world;
    moved.camera.position += offset;
    moved.camera.target += offset;
    for (Light& light : moved.lights) light.position += offset;
    if (moved.explicitBounds) {
        moved.explicitBounds->min += offset;
        moved.explicitBounds->max += offset;
    }
    return moved;
}

float nearestDepthFrom(const Scene& scene, const Light& light) {
    if (light.type == Light::Type::Directional) return 0.0f;
    const glm::vec3 dir = safeDirection(light.direction);
    float nearest = std::numeric_limits<float>::max();
    std::map<const Mesh*, std::pair<glm::vec3, glm::vec3>> meshBoxes;  // instanced meshes: one box each
    for (const SceneObject& object : scene.objects) {
        if (!object.mesh || object.mesh->positions.empty()) continue;
        auto box = meshBoxes.find(object.mesh.get());
        if (box == meshBoxes.end())
            box = meshBoxes
                      .emplace(object.mesh.get(),
                               std::make_pair(object.mesh->boundsMin(), object.mesh->boundsMax()))
                      .first;
        const auto& [lo, hi] = box->second;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 local(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y,
                                  corner & 4 ? hi.z : lo.z);
            const float depth =
                glm::dot(glm::vec3(object.world * glm::vec4(local, 1.0f)) - light.position, dir);
            if (!(depth > 0.0f)) return 0.0f;  // reaches behind the light: no safe near plane from boxes
            nearest = std::min(nearest, depth);
        }
    }
    return nearest == std::numeric_limits<float>::max() ? 0.0f : nearest;
}

glm::vec3 renderOrigin(const Scene& scene) {
    if (scene.objects.empty() && !scene.explicitBounds) return glm::vec3(0.0f);
    return renderOrigin(scene.bounds());
}

glm::vec3 renderOrigin(const Bounds& sceneBounds) {
    const glm::vec3 centre = sceneBounds.center();
    const float farthest = std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)});
    return farthest > 16.0f * std::max(sceneBounds.radius(), 1e-6f) && std::isfinite(farthest)
               ? centre
               : glm::vec3(0.0f);
}

Bounds Scene::bounds() const {
    return explicitBounds ? *explicitBounds : objectBounds();
}

Bounds Scene::objectBounds() const {
    Bounds result;
    result.min = glm::vec3(std::numeric_limits<float>::max());
    result.max = glm::vec3(std::numeric_limits<float>::lowest());
    bool any = false;
    for (const auto& object : objects) {
        if (!object.mesh) continue;
        for (const auto& p : object.mesh->positions) {
            glm::vec3 w = glm::vec3(object.world * glm::vec4(p, 1.0f));
            result.min = glm::min(result.min, w);
            result.max = glm::max(result.max, w);
            any = true;
        }
    }
    return any ? result : Bounds{};
}

namespace {
bool sameIgnoringCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}
}  // namespace

// D3D's names are case-blind, and FX Composer's SAS binds `Object = "PointLight0"` (also SpotLight0,
// DirectionalLight0) to the scene's first light whatever its type: an exact match first, then the name
// without regard to case, then the light type prefix dropped.
const Light* Scene::findLight(std::string_view lightName) const {
    countNameLookup();
    for (const auto& light : lights)
        if (light.name == lightName) return &light;
    for (const auto& light : lights)
        if (sameIgnoringCase(light.name, lightName)) return &light;
    for (std::string_view prefix : {"Point", "Spot", "Directional", "Dir"}) {
        if (lightName.size() > prefix.size() &&
            sameIgnoringCase(lightName.substr(0, prefix.size()), prefix)) {
            const std::string_view rest = lightName.substr(prefix.size());
            if (rest.size() > 5 && sameIgnoringCase(rest.substr(0, 5), "light")) return findLight(rest);
        }
    }
    // "lightN" in a scene that names none of its lights so: the N-th light (effects number their lights; a
    // scene file may name its lights "sun" and "lamp"). A scene that names some "lightK" means those names:
    // falling back there could make two numbers one light.
    const auto lightNumber = [](std::string_view name) -> int {
        if (name.size() < 6 || name.size() > 7 || !sameIgnoringCase(name.substr(0, 5), "light")) return -1;
        const std::string_view digits = name.substr(5);
        if (!std::all_of(digits.begin(), digits.end(),
                         [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }))
            return -1;
        return std::stoi(std::string(digits));
    };
    const int n = lightNumber(lightName);
    const bool namesNumbers = std::any_of(lights.begin(), lights.end(),
                                          [&](const Light& light) { return lightNumber(light.name) >= 0; });
    if (n >= 0 && !namesNumbers && static_cast<size_t>(n) < lights.size())
        return &lights[static_cast<size_t>(n)];
    return nullptr;
}

size_t Scene::triangleCount() const {
    size_t count = 0;
    for (const auto& object : objects)
        if (object.mesh) count += object.mesh->triangleCount();
    return count;
}

bool segmentOccluded(const Scene& scene, const glm::vec3& from, const glm::vec3& to) {
    const glm::vec3 dir = to - from;
    const float length = glm::length(dir);
    if (length <= 0.0f) return false;
    // Hits within 1e-3 world units of either end belong to the surfaces the end points lie on.
    const float epsilon = std::min(1e-3f / length, 0.25f);
    const float tMin = epsilon, tMax = 1.0f - epsilon;
    for (const auto& object : scene.objects) {
        if (!object.castsShadow || !object.mesh) continue;
        const Mesh& mesh = *object.mesh;
        std::vector<glm::vec3> world(mesh.positions.size());
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
        for (size_t i = 0; i < world.size(); ++i) {
            world[i] = glm::vec3(object.world * glm::vec4(mesh.positions[i], 1.0f));
            lo = glm::min(lo, world[i]);
            hi = glm::max(hi, world[i]);
        }
        if (world.empty() || !segmentHitsBox(from, dir, tMin, tMax, lo, hi)) continue;
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            auto hit = intersect(from, dir, world[mesh.indices[t]], world[mesh.indices[t + 1]],
                                 world[mesh.indices[t + 2]]);
            if (hit && *hit > tMin && *hit < tMax) return true;
        }
    }
    return false;
}

std::optional<glm::vec3> projectToPixel(const Scene& scene, const glm::vec3& world, int width, int height) {
    if (width <= 0 || height <= 0) return std::nullopt;
    const float aspect = float(width) / float(height);
    const glm::vec4 clip = scene.camera.projection(aspect) * scene.camera.view() * glm::vec4(world, 1.0f);
    if (clip.w <= 0.0f) return std::nullopt;  // behind the camera
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    if (ndc.x < -1.0f || ndc.x > 1.0f || ndc.y < -1.0f || ndc.y > 1.0f || ndc.z < 0.0f || ndc.z > 1.0f) {
        return std::nullopt;
    }
    return glm::vec3((ndc.x + 1.0f) * 0.5f * float(width), (1.0f - ndc.y) * 0.5f * float(height), ndc.z);
}

}  // namespace runtime
