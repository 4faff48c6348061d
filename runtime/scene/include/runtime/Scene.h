// Scene: what a frame shows: objects (mesh + transform + colour), a camera and lights, with the matrices
// the runtime binds to effect semantics. All matrices are D3DX-style: they transform row vectors
// (mul(v, M)), translation in the fourth row, left-handed, clip depth in [0, 1]. Stored in glm::mat4,
// whose memory layout then equals the D3DX matrix row by row (glm's column-vector M equals D3D's M^T).
#pragma once

#include <runtime/Mesh.h>

#include <glm/glm.hpp>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace runtime {

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 center() const { return (min + max) * 0.5f; }
    float radius() const;  // half the diagonal
};

struct SceneObject {
    std::string name;
    std::shared_ptr<const Mesh> mesh;
    glm::mat4 world{1.0f};  // object -> world (glm column-vector form)
    glm::vec3 color{0.8f};  // diffuse colour, bound to the DIFFUSE / MaterialDiffuse semantics
    bool castsShadow = true;
    bool receivesShadow = true;
    uint32_t id = 0;  // object id (1-based), for ID-buffer methods
};

struct Camera {
    glm::vec3 position{0.0f, 5.0f, -10.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovY = glm::radians(60.0f);  // radians
    float nearPlane = 0.1f;
    float farPlane = 100.0f;

    glm::mat4 view() const;                    // lookAtLH
    glm::mat4 projection(float aspect) const;  // perspectiveLH_ZO
};

struct Light {
    enum class Type { Directional, Spot, Point };
    std::string name = "light0";  // what RenderPort=... and frustum="..." annotations name
    Type type = Type::Directional;
    glm::vec3 position{0.0f, 10.0f, 0.0f};   // spot/point; for directional, only where the view is placed
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // normalized, pointing from the light into the scene
    glm::vec3 color{1.0f};
    float spotAngle = glm::radians(60.0f);  // full cone angle (spot)
    float areaRadius = 0.0f;                // soft-shadow light size (0 = point-like)

    // The light's view and projection, fitted to `bounds` (what the shadow map must cover):
    // directional: orthographic box around the bounds, looking along `direction`;
    // spot: perspective with the cone angle, near/far enclosing the bounds.
    // `nearestDepth` (spot/point, see nearestDepthFrom): how far in front of the light the nearest object
    // starts; the near plane moves out to it where the bounds alone would put it at ~0.
    glm::mat4 view(const Bounds& bounds) const;
    glm::mat4 projection(const Bounds& bounds, float nearestDepth = 0.0f) const;
};

struct Scene {
    std::string name;
    std::vector<SceneObject> objects;
    Camera camera;
    std::vector<Light> lights;
    glm::vec3 ambient{0.15f};
    // What the shadow map must cover, where the scene says so (a scene file's "bounds"); else the objects'.
    std::optional<Bounds> explicitBounds;
    // Hints from the setup a scene reproduces (Scherzer 2005 §5: 512x512 viewport, 2048^2 map); 0 = none.
    glm::ivec2 suggestedViewport{0};
    int suggestedMapSize = 0;

    Bounds bounds() const;        // explicitBounds if set, else objectBounds()
    Bounds objectBounds() const;  // of all objects in world space
    // The light an effect names: by name, then ignoring case, then without a Point/Spot/Directional/Dir
    // prefix, then "lightN" as the N-th light where no light is named "lightK"; null for none.
    const Light* findLight(std::string_view lightName) const;
    size_t triangleCount() const;
    // The whole configuration moved by `offset`: objects, camera, lights and explicit bounds.
    Scene translated(const glm::vec3& offset) const;
};

// How far along a spot or point light's direction the nearest object begins (its world bounding box's
// nearest corner), or 0 if some object reaches behind the light's plane or there is none. A light inside the
// scene's bounds would otherwise get a near plane of ~0, squeezing every clip depth towards 1 so that a
// constant bias in clip depth swallows whole objects (stress case spot-inside-bounds).
float nearestDepthFrom(const Scene& scene, const Light& light);

// Camera-relative rendering. Float32 world coordinates near 1e6 resolve only 1/16 of a unit, and a shader
// that transforms a vertex to world space and then subtracts a camera's or light's equally large
// translation keeps nothing below that: a scene far from the origin gets shadow acne everywhere (stress
// case far-from-origin). EffectRenderer therefore renders a scene translated by -renderOrigin(scene): the
// subtraction of two nearby floats is exact (Sterbenz), so the GPU only sees small coordinates and every
// semantic (World, View, CameraPosition, light positions) is relative to that origin. The origin is the
// centre of the bounds when the scene lies more than 16 bounding radii from the world origin, else zero
// (no copy, no change).
glm::vec3 renderOrigin(const Scene& scene);
glm::vec3 renderOrigin(const Bounds& sceneBounds);  // the same, from the scene's bounds

// Exact visibility: true if the open segment from `from` to `to` hits a triangle of a shadow-casting
// object (brute force Möller-Trumbore; the scenes here are small). What tests use to find points that lie
// in a shadow, independently of any shadow map.
bool segmentOccluded(const Scene& scene, const glm::vec3& from, const glm::vec3& to);

// World -> pixel coordinates (x right, y down, origin top-left) and depth for a `width` x `height` image
// of the scene's camera; nullopt if behind the camera or outside the image.
std::optional<glm::vec3> projectToPixel(const Scene& scene, const glm::vec3& world, int width, int height);

}  // namespace runtime
