// Scene: D3DX camera/light matrices, built-in scenes, exact segment visibility and world-to-pixel projection.
#include <runtime/BuiltinScenes.h>
#include <runtime/Scene.h>

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <set>

namespace test_scene {

using namespace runtime;

namespace {

Scene builtin(std::string_view name) {
    auto scene = makeBuiltinScene(name);
    EXPECT_TRUE(scene.has_value()) << name;
    return scene ? *scene : Scene{};
}

glm::vec3 toWorld(const SceneObject& object, const glm::vec3& p) {
    return glm::vec3(object.world * glm::vec4(p, 1.0f));
}

glm::vec3 clipToNdc(const glm::vec4& clip) {
    return glm::vec3(clip) / clip.w;
}

// Signed area of a pixel-space triangle (x right, y down): positive when clockwise on screen.
float pixelCross(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    glm::vec2 ab(b - a), ac(c - a);
    return ab.x * ac.y - ab.y * ac.x;
}

const SceneObject* findObject(const Scene& scene, std::string_view name) {
    for (const auto& object : scene.objects)
        if (object.name == name) return &object;
    return nullptr;
}

constexpr int kWidth = 640, kHeight = 480;

}  // namespace

TEST(Scene, BuiltinScenesExist) {
    auto names = builtinSceneNames();
    // The three original scenes come first, unchanged; tests/runtime/test_builtin_scenes.cpp covers the rest.
    ASSERT_GE(names.size(), 3u);
    EXPECT_EQ(std::vector<std::string>(names.begin(), names.begin() + 3),
              (std::vector<std::string>{"boxes", "torus", "teapot"}));
    EXPECT_FALSE(makeBuiltinScene("no such scene").has_value());
    for (const auto& name : names) {
        Scene scene = builtin(name);
        EXPECT_EQ(scene.name, name);
        ASSERT_FALSE(scene.lights.empty());
        EXPECT_EQ(scene.lights[0].name, "light0");
        EXPECT_EQ(scene.findLight("light0"), &scene.lights[0]);
        EXPECT_EQ(scene.findLight("light7"), nullptr);
        std::set<uint32_t> ids;
        size_t triangles = 0;
        for (const auto& object : scene.objects) {
            ASSERT_TRUE(object.mesh);
            EXPECT_GE(object.id, 1u);
            EXPECT_TRUE(ids.insert(object.id).second) << "duplicate id " << object.id;
            triangles += object.mesh->triangleCount();
        }
        EXPECT_EQ(scene.triangleCount(), triangles);
        EXPECT_NEAR(glm::length(scene.lights[0].direction), 1.0f, 1e-5f);
    }
}

TEST(Scene, BoxesLayout) {
    Scene scene = builtin("boxes");
    ASSERT_EQ(scene.objects.size(), 3u);
    EXPECT_EQ(scene.objects[0].id, 1u);
    EXPECT_FALSE(scene.objects[0].mesh->closed);
    EXPECT_TRUE(scene.objects[1].mesh->closed);
    EXPECT_TRUE(scene.objects[2].mesh->closed);
    EXPECT_EQ(scene.lights[0].type, Light::Type::Directional);
    // Distinct colours.
    for (size_t i = 0; i < scene.objects.size(); ++i)
        for (size_t j = i + 1; j < scene.objects.size(); ++j)
            EXPECT_GT(glm::length(scene.objects[i].color - scene.objects[j].color), 0.1f);
    // The plane spans 20 x 20 at y = 0; the sphere (r = 1.2 on the plane) is the highest point.
    Bounds bounds = scene.bounds();
    EXPECT_NEAR(bounds.min.x, -10.0f, 1e-4f);
    EXPECT_NEAR(bounds.max.z, 10.0f, 1e-4f);
    EXPECT_NEAR(bounds.min.y, 0.0f, 1e-4f);
    EXPECT_NEAR(bounds.max.y, 2.4f, 1e-4f);
    EXPECT_NEAR(bounds.radius(), glm::length(bounds.max - bounds.min) / 2.0f, 1e-5f);
    // Every object rests on the plane.
    for (const auto& object : scene.objects) {
        float lowest = std::numeric_limits<float>::max();
        for (const auto& p : object.mesh->positions) lowest = std::min(lowest, toWorld(object, p).y);
        EXPECT_NEAR(lowest, 0.0f, 1e-4f) << object.name;
    }
}

TEST(Scene, CameraIsD3DXLeftHanded) {
    Camera camera;
    camera.position = glm::vec3(1.0f, 2.0f, -8.0f);
    camera.target = glm::vec3(1.0f, 2.0f, 0.0f);
    glm::mat4 view = camera.view();
    // Eye at the origin, looking down +z (left-handed), +x to the right.
    glm::vec3 eye = glm::vec3(view * glm::vec4(camera.position, 1.0f));
    EXPECT_NEAR(glm::length(eye), 0.0f, 1e-5f);
    glm::vec3 ahead = glm::vec3(view * glm::vec4(camera.target, 1.0f));
    EXPECT_NEAR(ahead.z, 8.0f, 1e-5f);
    EXPECT_GT((view * glm::vec4(2.0f, 2.0f, 0.0f, 1.0f)).x, 0.0f);
    // Depth in [0, 1] from the near to the far plane.
    glm::mat4 projection = camera.projection(1.5f);
    EXPECT_NEAR(clipToNdc(projection * glm::vec4(0, 0, camera.nearPlane, 1)).z, 0.0f, 1e-5f);
    EXPECT_NEAR(clipToNdc(projection * glm::vec4(0, 0, camera.farPlane, 1)).z, 1.0f, 1e-5f);
    // The vertical field of view: a point at the top edge of the frustum maps to y = 1.
    const float depth = 5.0f;
    EXPECT_NEAR(clipToNdc(projection * glm::vec4(0, depth * std::tan(camera.fovY / 2), depth, 1)).y, 1.0f,
                1e-5f);
    // D3DX layout: translation in the fourth row = glm's fourth column, which is what glm stores last.
    EXPECT_EQ(&view[3][0] - &view[0][0], 12);
}

TEST(Scene, FrontFacesAreClockwiseOnScreen) {
    // The plane of "boxes", seen from a camera above it: its triangles face +y, towards the camera, and
    // must appear clockwise in pixel space (y down).
    Scene scene = builtin("boxes");
    const SceneObject& ground = scene.objects[0];
    const Mesh& plane = *ground.mesh;
    int checked = 0;
    for (size_t t = 0; t < plane.triangleCount(); ++t) {
        std::optional<glm::vec3> pixels[3];
        for (int k = 0; k < 3; ++k)
            pixels[k] = projectToPixel(scene, toWorld(ground, plane.positions[plane.indices[t * 3 + k]]),
                                       kWidth, kHeight);
        if (!pixels[0] || !pixels[1] || !pixels[2]) continue;
        EXPECT_GT(pixelCross(*pixels[0], *pixels[1], *pixels[2]), 0.0f) << "triangle " << t;
        ++checked;
    }
    EXPECT_GT(checked, 0);

    // Every triangle of every scene: clockwise on screen exactly when its winding normal faces the camera.
    for (const auto& name : builtinSceneNames()) {
        Scene s = builtin(name);
        for (const auto& object : s.objects) {
            const Mesh& mesh = *object.mesh;
            for (size_t t = 0; t < mesh.triangleCount(); ++t) {
                glm::vec3 w[3];
                std::optional<glm::vec3> px[3];
                for (int k = 0; k < 3; ++k) {
                    w[k] = toWorld(object, mesh.positions[mesh.indices[t * 3 + k]]);
                    px[k] = projectToPixel(s, w[k], kWidth, kHeight);
                }
                if (!px[0] || !px[1] || !px[2]) continue;
                float area = pixelCross(*px[0], *px[1], *px[2]);
                float facing = glm::dot(glm::cross(w[1] - w[0], w[2] - w[0]), s.camera.position - w[0]);
                if (std::abs(area) < 1e-2f || std::abs(facing) < 1e-6f) continue;  // edge-on
                EXPECT_EQ(area > 0.0f, facing > 0.0f) << name << "/" << object.name << " triangle " << t;
            }
        }
    }
}

TEST(Scene, ProjectToPixel) {
    Scene scene = builtin("boxes");
    // The camera's target lands in the image centre.
    auto centre = projectToPixel(scene, scene.camera.target, kWidth, kHeight);
    ASSERT_TRUE(centre);
    EXPECT_NEAR(centre->x, kWidth / 2.0f, 1e-2f);
    EXPECT_NEAR(centre->y, kHeight / 2.0f, 1e-2f);
    EXPECT_GT(centre->z, 0.0f);
    EXPECT_LT(centre->z, 1.0f);
    // Corners: world points unprojected from just inside the NDC corners come back at the pixel corners,
    // NDC y = +1 at the top (pixel y = 0).
    const glm::mat4 inverse =
        glm::inverse(scene.camera.projection(float(kWidth) / kHeight) * scene.camera.view());
    auto unproject = [&](float x, float y, float z) {
        glm::vec4 p = inverse * glm::vec4(x, y, z, 1.0f);
        return glm::vec3(p) / p.w;
    };
    const float inside = 0.999f;
    struct Corner {
        float ndcX, ndcY, pixelX, pixelY;
    } corners[] = {{-1, 1, 0, 0}, {1, 1, kWidth, 0}, {-1, -1, 0, kHeight}, {1, -1, kWidth, kHeight}};
    for (const auto& corner : corners) {
        auto pixel = projectToPixel(scene, unproject(corner.ndcX * inside, corner.ndcY * inside, 0.5f),
                                    kWidth, kHeight);
        ASSERT_TRUE(pixel);
        EXPECT_NEAR(pixel->x, corner.pixelX, 0.001f * kWidth);
        EXPECT_NEAR(pixel->y, corner.pixelY, 0.001f * kHeight);
        EXPECT_NEAR(pixel->z, 0.5f, 1e-3f);
        // Just outside the image: nothing.
        EXPECT_FALSE(projectToPixel(scene, unproject(corner.ndcX * 1.01f, corner.ndcY * 1.01f, 0.5f), kWidth,
                                    kHeight));
    }
    // Behind the camera: nothing, even where the perspective divide would bring it back into range.
    glm::vec3 forward = glm::normalize(scene.camera.target - scene.camera.position);
    EXPECT_FALSE(projectToPixel(scene, scene.camera.position - forward * 5.0f, kWidth, kHeight));
    // Beyond the far plane: nothing.
    EXPECT_FALSE(projectToPixel(scene, scene.camera.position + forward * (scene.camera.farPlane * 1.1f),
                                kWidth, kHeight));
}

TEST(Scene, DirectionalLightLooksAlongItsDirection) {
    Scene scene = builtin("boxes");
    const Light& light = scene.lights[0];
    const Bounds bounds = scene.bounds();
    const glm::mat4 viewProjection = light.projection(bounds) * light.view(bounds);
    // Orthographic: w = 1, and moving along the light direction only increases clip z.
    glm::vec4 a = viewProjection * glm::vec4(bounds.center(), 1.0f);
    glm::vec4 b = viewProjection * glm::vec4(bounds.center() + light.direction, 1.0f);
    EXPECT_NEAR(a.w, 1.0f, 1e-5f);
    EXPECT_NEAR(b.x - a.x, 0.0f, 1e-5f);
    EXPECT_NEAR(b.y - a.y, 0.0f, 1e-5f);
    EXPECT_GT(b.z - a.z, 0.0f);
    // The bounds' centre is in the middle of the map.
    EXPECT_NEAR(a.x, 0.0f, 1e-5f);
    EXPECT_NEAR(a.y, 0.0f, 1e-5f);
    EXPECT_NEAR(a.z, 0.5f, 0.01f);

    // Straight down: lookAt's usual +y up would be parallel; the matrices must stay finite and still work.
    Light down = light;
    down.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    const glm::mat4 m = down.projection(bounds) * down.view(bounds);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(m[c][r]));
    glm::vec4 top = m * glm::vec4(bounds.center() + glm::vec3(0, 1, 0), 1.0f);
    glm::vec4 bottom = m * glm::vec4(bounds.center() - glm::vec3(0, 1, 0), 1.0f);
    EXPECT_LT(top.z, bottom.z);
}

TEST(Scene, SpotAndPointLightProjections) {
    Scene scene = builtin("torus");
    const Light& spot = scene.lights[0];
    EXPECT_EQ(spot.type, Light::Type::Spot);
    const Bounds bounds = scene.bounds();
    const glm::mat4 projection = spot.projection(bounds);
    // perspectiveLH_ZO(spotAngle, 1, ...): y scale = cot(angle / 2), square.
    EXPECT_NEAR(projection[1][1], 1.0f / std::tan(spot.spotAngle / 2.0f), 1e-4f);
    EXPECT_NEAR(projection[0][0], projection[1][1], 1e-5f);
    const glm::mat4 viewProjection = projection * spot.view(bounds);
    glm::vec3 axis = clipToNdc(viewProjection * glm::vec4(spot.position + spot.direction * 5.0f, 1.0f));
    EXPECT_NEAR(axis.x, 0.0f, 1e-4f);
    EXPECT_NEAR(axis.y, 0.0f, 1e-4f);
    EXPECT_LT(clipToNdc(viewProjection * glm::vec4(spot.position + spot.direction * 5.0f, 1.0f)).z,
              clipToNdc(viewProjection * glm::vec4(spot.position + spot.direction * 10.0f, 1.0f)).z);

    // Point lights are treated as 90-degree spot lights for now.
    Light point = spot;
    point.type = Light::Type::Point;
    EXPECT_NEAR(point.projection(bounds)[1][1], 1.0f, 1e-4f);

    // A light inside the bounds: the near plane stays positive.
    Light inside = spot;
    inside.position = bounds.center();
    glm::mat4 p = inside.projection(bounds);
    float nearPlane = -p[3][2] / p[2][2];  // perspectiveLH_ZO: z_clip = f/(f-n) z - f n/(f-n)
    EXPECT_GT(nearPlane, 0.0f);
}

TEST(Scene, EveryVertexFitsTheLightAndTheCamera) {
    for (const auto& name : builtinSceneNames()) {
        Scene scene = builtin(name);
        const Bounds bounds = scene.bounds();
        for (const auto& light : scene.lights) {
            const glm::mat4 viewProjection = light.projection(bounds) * light.view(bounds);
            for (const auto& object : scene.objects) {
                for (const auto& p : object.mesh->positions) {
                    glm::vec4 clip = viewProjection * glm::vec4(toWorld(object, p), 1.0f);
                    ASSERT_GT(clip.w, 0.0f);
                    glm::vec3 ndc = clipToNdc(clip);
                    ASSERT_TRUE(std::abs(ndc.x) <= 1.0f && std::abs(ndc.y) <= 1.0f && ndc.z >= 0.0f &&
                                ndc.z <= 1.0f)
                        << name << "/" << object.name << " (" << ndc.x << ", " << ndc.y << ", " << ndc.z
                        << ")";
                }
            }
        }
        // Everything but the ground (larger than the view on purpose) is in the image: in the three small
        // scenes; "forest" and "behind" are larger than the view on purpose (test_builtin_scenes.cpp).
        if (name == "forest" || name == "forest-fifth" || name == "behind") continue;
        for (const auto& object : scene.objects) {
            if (object.name == "ground") continue;
            for (const auto& p : object.mesh->positions)
                ASSERT_TRUE(projectToPixel(scene, toWorld(object, p), kWidth, kHeight))
                    << name << "/" << object.name;
        }
    }
}

TEST(Scene, SegmentOccluded) {
    Scene scene = builtin("boxes");
    const SceneObject* box = findObject(scene, "box");
    ASSERT_TRUE(box);
    const glm::vec3 centre = toWorld(*box, glm::vec3(0.0f));
    const glm::vec3 half = (box->mesh->boundsMax() - box->mesh->boundsMin()) * 0.5f;
    // Through the box, and beside / above it.
    EXPECT_TRUE(segmentOccluded(scene, centre + glm::vec3(0, 0, -5), centre + glm::vec3(0, 0, 5)));
    EXPECT_FALSE(segmentOccluded(scene, centre + glm::vec3(0, half.y + 0.1f, -5),
                                 centre + glm::vec3(0, half.y + 0.1f, 5)));
    EXPECT_FALSE(
        segmentOccluded(scene, centre + glm::vec3(0, 0, -5), centre + glm::vec3(0, 0, -half.z - 0.1f)));
    // Ending or starting on a surface does not count: a point on the box's top sees the sky.
    const glm::vec3 top = centre + glm::vec3(0, half.y, 0);
    EXPECT_FALSE(segmentOccluded(scene, top, top + glm::vec3(0, 10, 0)));
    EXPECT_FALSE(segmentOccluded(scene, top + glm::vec3(0, 10, 0), top));
    // Under the box (on the plane, on the box's bottom face): the top face is in the way.
    const glm::vec3 under = centre - glm::vec3(0, half.y, 0);
    EXPECT_TRUE(segmentOccluded(scene, under, under + glm::vec3(0, 10, 0)));
    // Objects that cast no shadow are ignored.
    Scene noCasters = scene;
    for (auto& object : noCasters.objects) object.castsShadow = false;
    EXPECT_FALSE(segmentOccluded(noCasters, centre + glm::vec3(0, 0, -5), centre + glm::vec3(0, 0, 5)));
    // A degenerate segment is never occluded.
    EXPECT_FALSE(segmentOccluded(scene, centre, centre));
}

TEST(Scene, BoxShadowIsVisibleOnThePlane) {
    // Plane points in the box's shadow (their segment towards the light is blocked) that the camera sees
    // (in the image and not hidden behind anything): what shadow-map image tests rely on.
    Scene scene = builtin("boxes");
    const Light& light = scene.lights[0];
    const float reach = 2.0f * scene.bounds().radius();
    Scene boxOnly = scene;
    for (auto& object : boxOnly.objects) object.castsShadow = object.name == "box";
    int visibleShadow = 0;
    for (float x = -6.0f; x <= 6.0f; x += 0.25f) {
        for (float z = -6.0f; z <= 6.0f; z += 0.25f) {
            glm::vec3 p(x, 0.0f, z);
            if (!projectToPixel(scene, p, kWidth, kHeight)) continue;
            if (segmentOccluded(scene, p, scene.camera.position)) continue;  // hidden from the camera
            if (segmentOccluded(boxOnly, p, p - light.direction * reach)) ++visibleShadow;
        }
    }
    // At least a square unit of visible shadow (16 samples at a 0.25 spacing).
    EXPECT_GE(visibleShadow, 16);
}
}  // namespace test_scene
