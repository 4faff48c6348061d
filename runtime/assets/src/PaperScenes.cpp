// The small test setups of the papers as built-in scenes:
//   "dual-l"       — Weiskopf & Ertl 2003, Fig. 5: an "L"-shaped solid above a greenish surface,
//                    directional light "from right above"; the crease between the L's legs shows midpoint
//                    self-unshadowing, its light-space silhouettes self-shadowing.
//   "double-torus" — Weiskopf & Ertl 2003, Fig. 6: a double torus over a plane (bilinear filtering).
//   "behind"       — Kozlov 2004 (PSM "Care and Feeding", §14.2): casters *behind* the viewer with the
//                    light behind too, whose shadows fall into the view; a long plane and rows of boxes and
//                    poles in front, so the view frustum is much smaller than the scene.
#include <private/runtime/SceneBuilding.h>

#include <runtime/MeshImporter.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <initializer_list>
#include <utility>

namespace runtime {

namespace {

void addFace(Mesh& mesh, const glm::vec3& normal, std::initializer_list<glm::vec3> polygonFan) {
    const auto first = static_cast<uint32_t>(mesh.positions.size());
    for (const auto& p : polygonFan) {
        mesh.positions.push_back(p);
        mesh.normals.push_back(normal);
    }
    const auto count = static_cast<uint32_t>(polygonFan.size());
    for (uint32_t i = 1; i + 1 < count; ++i) {
        uint32_t a = first, b = first + i, c = first + i + 1;
        // Orient against the face normal: clockwise front faces (Mesh.h).
        if (glm::dot(glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]),
                     normal) < 0.0f)
            std::swap(b, c);
        mesh.indices.insert(mesh.indices.end(), {a, b, c});
    }
}

// An "L" prism: in the xy plane a vertical leg (x in [0, thickness], y in [0, height]) and a foot (x in
// [0, width], y in [0, thickness]), extruded over z in [-depth/2, depth/2]. Closed, one normal per face.
Mesh makeLPrism(float width, float height, float thickness, float depth) {
    Mesh mesh;
    mesh.name = "L";
    const float z0 = -0.5f * depth, z1 = 0.5f * depth;
    // The outline counter-clockwise in xy; (t, t) is the reflex corner (Weiskopf & Ertl, Fig. 5).
    const glm::vec2 outline[6] = {
        {0, 0}, {width, 0}, {width, thickness}, {thickness, thickness}, {thickness, height}, {0, height}};
    for (int i = 0; i < 6; ++i) {
        const glm::vec2 a = outline[i], b = outline[(i + 1) % 6];
        const glm::vec2 edge = b - a;
        const glm::vec3 normal =
            glm::normalize(glm::vec3(edge.y, -edge.x, 0.0f));  // outward for a CCW outline
        addFace(mesh, normal, {{a, z0}, {b, z0}, {b, z1}, {a, z1}});
    }
    // Caps: a fan from the reflex corner covers the non-convex L without T-junctions.
    for (float z : {z0, z1}) {
        const glm::vec3 normal(0.0f, 0.0f, z < 0.0f ? -1.0f : 1.0f);
        const glm::vec3 r(thickness, thickness, z);
        addFace(mesh, normal,
                {r, {thickness, height, z}, {0, height, z}, {0, 0, z}, {width, 0, z}, {width, thickness, z}});
    }
    mesh.closed = true;
    return mesh;
}

SceneObject ground(float sizeX, float sizeZ, const glm::vec3& color) {
    const int divisions = static_cast<int>(std::max(sizeX, sizeZ) / 2.0f);
    return placeObject("ground", share(makePlane(sizeX, sizeZ, std::max(divisions, 10))), glm::mat4(1.0f),
                       color, 1);
}

}  // namespace

Scene makeDualLScene() {
    Scene scene;
    scene.name = "dual-l";
    // Weiskopf & Ertl 2003, Fig. 5: "a simple 'L'-shaped object above a greenish surface".
    scene.objects.push_back(ground(12.0f, 12.0f, glm::vec3(0.45f, 0.65f, 0.4f)));
    Mesh l = makeLPrism(3.0f, 3.0f, 0.8f, 2.0f);
    // Floating 0.5 above the plane, the foot pointing right (+x), so the light from the right strikes the
    // inner crease and the upright leg shadows the ground to the left.
    scene.objects.push_back(placeObject("L", share(std::move(l)),
                                        glm::translate(glm::mat4(1.0f), glm::vec3(-1.5f, 0.5f, 0.0f)),
                                        glm::vec3(0.85f, 0.8f, 0.7f), 2));
    scene.camera.position = glm::vec3(0.5f, 4.5f, -9.0f);
    scene.camera.target = glm::vec3(0.0f, 1.2f, 0.0f);
    // "Directional light comes from right above" (Fig. 5's caption): mostly down, tilted from +x.
    scene.lights.push_back(fittedDirectionalLight(glm::vec3(-0.55f, -1.0f, 0.15f), scene.bounds()));
    return scene;
}

Scene makeDoubleTorusScene() {
    Scene scene;
    scene.name = "double-torus";
    scene.objects.push_back(ground(12.0f, 12.0f, glm::vec3(0.45f, 0.65f, 0.4f)));
    // A genus-2 solid as two tori whose tubes merge in the middle. The union is not one manifold (the tubes
    // interpenetrate where they join), but every ray still enters and leaves it in pairs, which is all that
    // the back-face and dual-layer methods of Weiskopf & Ertl 2003 need from a closed object.
    const float major = 1.2f, minor = 0.4f;
    Mesh doubleTorus;
    doubleTorus.name = "double-torus";
    const Mesh ring = makeTorus(major, minor, 48, 24);
    appendMesh(doubleTorus, ring, glm::vec3(-(major - 0.5f * minor), 0.0f, 0.0f));
    appendMesh(doubleTorus, ring, glm::vec3(major - 0.5f * minor, 0.0f, 0.0f));
    // Tilted towards the camera so both holes show, lifted clear of the plane.
    const glm::mat4 world =
        composeTransform(glm::vec3(0.0f, 1.6f, 0.0f), glm::vec3(-25.0f, 10.0f, 0.0f), glm::vec3(1.0f));
    scene.objects.push_back(
        placeObject("double-torus", share(std::move(doubleTorus)), world, glm::vec3(0.8f, 0.55f, 0.3f), 2));
    scene.camera.position = glm::vec3(0.5f, 5.0f, -8.0f);
    scene.camera.target = glm::vec3(0.0f, 1.0f, 0.0f);
    scene.lights.push_back(fittedDirectionalLight(glm::vec3(-0.45f, -1.0f, 0.2f), scene.bounds()));
    return scene;
}

Scene makeBehindScene() {
    Scene scene;
    scene.name = "behind";
    // A long strip: the camera sees a small part of it, as in Kozlov 2004's problem cases.
    scene.objects.push_back(ground(60.0f, 240.0f, glm::vec3(0.7f, 0.7f, 0.65f)));
    auto pole = share(makeBox(glm::vec3(0.6f, 10.0f, 0.6f)));
    auto block = share(makeBox(glm::vec3(3.0f, 6.0f, 3.0f)));
    auto crate = share(makeBox(glm::vec3(2.0f)));
    uint32_t id = 2;
    // Behind the camera (z = -20): a row of tall poles and a row of blocks. With the light behind the
    // viewer too, their shadows stretch forward (+z) into the view: Kozlov's Fig. 14-1 case, where a PSM
    // that only focuses on the view frustum loses these casters.
    for (int i = 0; i < 7; ++i) {
        const float x = -12.0f + 4.0f * float(i);
        scene.objects.push_back(placeObject("pole" + std::to_string(i), pole,
                                            glm::translate(glm::mat4(1.0f), glm::vec3(x, 5.0f, -26.0f)),
                                            glm::vec3(0.55f, 0.35f, 0.25f), id++));
    }
    for (int i = 0; i < 4; ++i) {
        const float x = -10.5f + 7.0f * float(i);
        scene.objects.push_back(placeObject("block" + std::to_string(i), block,
                                            glm::translate(glm::mat4(1.0f), glm::vec3(x, 3.0f, -33.0f)),
                                            glm::vec3(0.3f, 0.4f, 0.6f), id++));
    }
    // In front: two rows of crates receding into the distance, the usual visible casters.
    for (int i = 0; i < 10; ++i) {
        for (float x : {-8.0f, 8.0f}) {
            scene.objects.push_back(
                placeObject("crate" + std::to_string(id), crate,
                            glm::translate(glm::mat4(1.0f), glm::vec3(x, 1.0f, -5.0f + 10.0f * float(i))),
                            glm::vec3(0.8f, 0.5f, 0.25f), id));
            ++id;
        }
    }
    scene.camera.position = glm::vec3(0.0f, 3.0f, -20.0f);
    scene.camera.target = glm::vec3(0.0f, 0.0f, 20.0f);
    scene.camera.farPlane = 150.0f;
    // The light behind the viewer (it travels +z, the way the camera looks), low, so the shadows are long.
    scene.lights.push_back(fittedDirectionalLight(glm::vec3(0.25f, -0.35f, 1.0f), scene.bounds()));
    return scene;
}

}  // namespace runtime
