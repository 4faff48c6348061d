// shadowfx-osg-peer: a shadowfx scene, or a case of `shadowfx stress`, rendered by OpenSceneGraph's
// osgShadow, for `shadowfx bench --peers osg` and `shadowfx stress --peers osg`.
//
// [SECTION] Options     command line
// [SECTION] Context     an EGL pbuffer with a compatibility-profile context, handed to osgViewer
// [SECTION] Scene       the scene file's geometry, camera and light as an OSG graph under a ShadowedScene
// [SECTION] Techniques  osgShadow's techniques by name
// [SECTION] Frames      warm-up, timed frames, the visibility frames (one per camera) and the JSON record
//
// The frame it writes is visibility only (lit 1, shadowed 0) without a shader of its own: lighting is off,
// every vertex is white where N·L > 0 (black elsewhere) and the ambient terms are zero, so osgShadow's own
// shaders multiply white by their shadow test. Techniques built on StandardShadowMap (LiSPSM) light in
// their own vertex shader whatever GL_LIGHTING says: for them the material's diffuse is so large that
// N·L > 0 saturates to white once the colour is clamped.
//
// shadowfx's world is left-handed (D3D); OSG's is right-handed. Mirroring z (geometry, camera and light
// alike) gives OSG the same picture, pixel for pixel, as shadowfx's G-buffer: a right-handed look-at and
// perspective of the mirrored world equal the left-handed ones of the original. The picture being the
// same, D3D's front faces still turn clockwise on screen; each triangle is reversed to make them GL's
// counter-clockwise front faces.
#include <runtime/Scene.h>
#include <runtime/SceneFile.h>
#include <runtime/StressCases.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <nlohmann/json.hpp>
#include <osg/CullFace>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LightModel>
#include <osg/LightSource>
#include <osg/Material>
#include <osg/MatrixTransform>
#include <osg/Texture2D>
#include <osg/Version>
#include <osgShadow/LightSpacePerspectiveShadowMap>
#include <osgShadow/ParallelSplitShadowMap>
#include <osgShadow/ShadowMap>
#include <osgShadow/ShadowedScene>
#include <osgShadow/SoftShadowMap>
#include <osgShadow/ViewDependentShadowMap>
#include <osgViewer/Viewer>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace {

const char* const kUsage =
    "usage: shadowfx-osg-peer --scene NAME|FILE.json --technique T --out-visibility V.pgm --out-json R.json\n"
    "                         [--map-size N] [--width W] [--height H] [--frames N] [--warmup N]\n"
    "                         [--light-direction X,Y,Z]\n"
    "       shadowfx-osg-peer --stress-case CASE --technique T --out-visibility V.pgm --out-json R.json ...\n"
    "  --technique  ShadowMap, SoftShadowMap, LiSPSM-VB, LiSPSM-CB, LiSPSM-DB, PSSM, VDSM-ortho-1,\n"
    "               VDSM-ortho-2, VDSM-persp-1, VDSM-persp-2 (or 'list' to print them)\n"
    "  --light-direction  override the light's direction (what `bench --light-angle-to-view` turned)\n"
    "  --stress-case  a case of `shadowfx stress` instead of a scene; V.pgm then holds one frame per\n"
    "               camera of the case's path, stacked top to bottom\n";

// Traversal masks: every object is drawn by the main camera; these bits say what it does for shadows.
constexpr unsigned kReceivesMask = 0x1;
constexpr unsigned kCastsMask = 0x2;
constexpr unsigned kDrawnMask = 0x4;

// [SECTION] Options

struct Options {
    std::string scene;
    std::string stressCase;
    std::string technique;
    std::string visibilityPath;
    std::string jsonPath;
    int mapSize = 1024;
    int width = 640;
    int height = 480;
    int frames = 10;
    int warmup = 2;
    bool overrideDirection = false;
    glm::vec3 lightDirection{0.0f, -1.0f, 0.0f};
};

bool parseInt(const char* text, int low, int high, int& out) {
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (*end != '\0' || value < low || value > high) return false;
    out = static_cast<int>(value);
    return true;
}

bool parseOptions(int argc, char** argv, Options& options, std::string& error) {
    for (int i = 1; i < argc; ++i) {
        const std::string name = argv[i];
        if (i + 1 >= argc) {
            error = name + " needs a value";
            return false;
        }
        const char* value = argv[++i];
        bool ok = true;
        if (name == "--scene") {
            options.scene = value;
        } else if (name == "--stress-case") {
            options.stressCase = value;
        } else if (name == "--technique") {
            options.technique = value;
        } else if (name == "--out-visibility") {
            options.visibilityPath = value;
        } else if (name == "--out-json") {
            options.jsonPath = value;
        } else if (name == "--map-size") {
            ok = parseInt(value, 1, 16384, options.mapSize);
        } else if (name == "--width") {
            ok = parseInt(value, 1, 16384, options.width);
        } else if (name == "--height") {
            ok = parseInt(value, 1, 16384, options.height);
        } else if (name == "--frames") {
            ok = parseInt(value, 1, 100000, options.frames);
        } else if (name == "--warmup") {
            ok = parseInt(value, 0, 100000, options.warmup);
        } else if (name == "--light-direction") {
            glm::vec3& d = options.lightDirection;
            ok = std::sscanf(value, "%f,%f,%f", &d.x, &d.y, &d.z) == 3 && glm::length(d) > 0.0f;
            if (ok) d = glm::normalize(d);
            options.overrideDirection = true;
        } else {
            error = "unknown option " + name;
            return false;
        }
        if (!ok) {
            error = name + ": invalid value '" + value + "'";
            return false;
        }
    }
    if (options.scene.empty() == options.stressCase.empty() || options.technique.empty() ||
        options.visibilityPath.empty() || options.jsonPath.empty()) {
        error =
            "--scene or --stress-case (one of them), --technique, --out-visibility and --out-json are "
            "required";
        return false;
    }
    return true;
}

// [SECTION] Context

// A pbuffer the size of the frame: osgViewer's embedded window draws into the context's default
// framebuffer, which a surfaceless context would not have. Compatibility profile: osgShadow's shaders use
// the fixed-function built-ins (gl_TexCoord, gl_EyePlaneS, gl_LightSource).
struct EglPbuffer {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLSurface surface = EGL_NO_SURFACE;
    EGLContext context = EGL_NO_CONTEXT;

    bool create(int width, int height, std::string& error) {
        auto getPlatformDisplay =
            reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (getPlatformDisplay)
            display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display == EGL_NO_DISPLAY) display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
        EGLint major = 0, minor = 0;
        if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
            error = "no EGL display";
            return false;
        }
        const EGLint configAttributes[] = {EGL_SURFACE_TYPE,
                                           EGL_PBUFFER_BIT,
                                           EGL_RENDERABLE_TYPE,
                                           EGL_OPENGL_BIT,
                                           EGL_RED_SIZE,
                                           8,
                                           EGL_GREEN_SIZE,
                                           8,
                                           EGL_BLUE_SIZE,
                                           8,
                                           EGL_ALPHA_SIZE,
                                           8,
                                           EGL_DEPTH_SIZE,
                                           24,
                                           EGL_NONE};
        EGLConfig config = nullptr;
        EGLint count = 0;
        if (!eglChooseConfig(display, configAttributes, &config, 1, &count) || count == 0) {
            error = "no EGL config with an RGBA8 + depth 24 pbuffer for desktop OpenGL";
            return false;
        }
        const EGLint surfaceAttributes[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
        surface = eglCreatePbufferSurface(display, config, surfaceAttributes);
        if (surface == EGL_NO_SURFACE) {
            error = "cannot create a " + std::to_string(width) + "x" + std::to_string(height) + " pbuffer";
            return false;
        }
        eglBindAPI(EGL_OPENGL_API);
        const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                            4,
                                            EGL_CONTEXT_MINOR_VERSION,
                                            5,
                                            EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                            EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                                            EGL_NONE};
        context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
        if (context == EGL_NO_CONTEXT) {
            const EGLint anyVersion[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
            context = eglCreateContext(display, config, EGL_NO_CONTEXT, anyVersion);
        }
        if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, surface, surface, context)) {
            error = "cannot create or bind a compatibility-profile OpenGL context";
            return false;
        }
        return true;
    }

    ~EglPbuffer() {
        if (display == EGL_NO_DISPLAY) return;
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
        if (surface != EGL_NO_SURFACE) eglDestroySurface(display, surface);
        eglTerminate(display);
    }
};

// [SECTION] Scene

osg::Vec3 mirrored(const glm::vec3& v) {
    return osg::Vec3(v.x, v.y, -v.z);
}

// shadowfx keeps D3DX row-vector matrices in glm's memory; osg::Matrix is row-vector too, so the 16 floats
// carry over as they are. Then the z mirror: world' = mirror * world * mirror (the mesh keeps its object
// space; the mirror at the end applies to the world, the one at the start undoes it for the object).
osg::Matrix mirroredWorld(const glm::mat4& world) {
    const osg::Matrix mirror = osg::Matrix::scale(1.0, 1.0, -1.0);
    return mirror * osg::Matrix(glm::value_ptr(world)) * mirror;
}

// The scene's shadow light: light0, else the first (as the ground truth picks it).
const runtime::Light* shadowLight(const runtime::Scene& scene) {
    if (const runtime::Light* light = scene.findLight("light0")) return light;
    return scene.lights.empty() ? nullptr : &scene.lights.front();
}

// One Geometry per object: positions, normals and indices shared per mesh, colours per object (white where
// the world-space normal faces the light). Positions are mirrored in object space (the mirrored world
// matrix mirrors them back and then into the right-handed world).
osg::ref_ptr<osg::Node> buildObject(const runtime::SceneObject& object, const runtime::Light& light,
                                    std::map<const runtime::Mesh*, osg::ref_ptr<osg::Geometry>>& shared) {
    const runtime::Mesh& mesh = *object.mesh;
    osg::ref_ptr<osg::Geometry>& base = shared[&mesh];
    if (!base) {
        base = new osg::Geometry;
        osg::ref_ptr<osg::Vec3Array> positions = new osg::Vec3Array;
        osg::ref_ptr<osg::Vec3Array> normals = new osg::Vec3Array;
        for (size_t i = 0; i < mesh.positions.size(); ++i) {
            positions->push_back(mirrored(mesh.positions[i]));
            normals->push_back(i < mesh.normals.size() ? mirrored(mesh.normals[i]) : osg::Vec3(0, 1, 0));
        }
        base->setVertexArray(positions);
        base->setNormalArray(normals, osg::Array::BIND_PER_VERTEX);
        // The mirror keeps the picture, so a D3D front face still turns clockwise on screen: reversing each
        // triangle makes it turn counter-clockwise, GL's front (osgShadow culls by facing in its map passes).
        osg::ref_ptr<osg::DrawElementsUInt> triangles = new osg::DrawElementsUInt(GL_TRIANGLES);
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            triangles->push_back(mesh.indices[i]);
            triangles->push_back(mesh.indices[i + 2]);
            triangles->push_back(mesh.indices[i + 1]);
        }
        base->addPrimitiveSet(triangles);
        base->setUseVertexBufferObjects(true);
        base->setUseDisplayList(false);
    }
    osg::ref_ptr<osg::Geometry> geometry = new osg::Geometry(*base, osg::CopyOp::SHALLOW_COPY);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(object.world)));
    osg::ref_ptr<osg::Vec4Array> colors = new osg::Vec4Array;
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3 n = i < mesh.normals.size() ? normalMatrix * mesh.normals[i] : glm::vec3(0, 1, 0);
        const glm::vec3 toLight =
            light.type == runtime::Light::Type::Directional
                ? -light.direction
                : light.position - glm::vec3(object.world * glm::vec4(mesh.positions[i], 1.0f));
        const float lit = glm::dot(n, toLight) > 0.0f ? 1.0f : 0.0f;
        colors->push_back(osg::Vec4(lit, lit, lit, 1.0f));
    }
    geometry->setColorArray(colors, osg::Array::BIND_PER_VERTEX);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(geometry);
    osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform(mirroredWorld(object.world));
    transform->addChild(geode);
    transform->setNodeMask(kDrawnMask | (object.castsShadow ? kCastsMask : 0u) |
                           (object.receivesShadow ? kReceivesMask : 0u));
    return transform;
}

// [SECTION] Techniques

const std::vector<std::string>& techniqueNames() {
    static const std::vector<std::string> names = {
        "ShadowMap", "SoftShadowMap", "LiSPSM-VB",    "LiSPSM-CB",    "LiSPSM-DB",
        "PSSM",      "VDSM-ortho-1",  "VDSM-ortho-2", "VDSM-persp-1", "VDSM-persp-2"};
    return names;
}

// The technique, configured for `mapSize` and a visibility-only frame. ViewDependentShadowMap's built-in
// shader reads one or two maps (ShadowSettings: more maps are fitted but not sampled), so 1 and 2 only.
osg::ref_ptr<osgShadow::ShadowTechnique> makeTechnique(const std::string& name, int mapSize,
                                                       osgShadow::ShadowedScene& scene, osg::Light* light) {
    const osg::Vec2s size(static_cast<short>(std::min(mapSize, 32767)),
                          static_cast<short>(std::min(mapSize, 32767)));
    if (name == "ShadowMap" || name == "SoftShadowMap") {
        osg::ref_ptr<osgShadow::ShadowMap> map =
            name == "ShadowMap" ? new osgShadow::ShadowMap : new osgShadow::SoftShadowMap;
        map->setTextureSize(size);
        map->setAmbientBias(osg::Vec2(0.0f, 1.0f));
        map->setLight(light);
        return map;
    }
    if (name.rfind("LiSPSM-", 0) == 0) {
        osg::ref_ptr<osgShadow::StandardShadowMap> map;
        if (name == "LiSPSM-VB") map = new osgShadow::LightSpacePerspectiveShadowMapVB;
        if (name == "LiSPSM-CB") map = new osgShadow::LightSpacePerspectiveShadowMapCB;
        if (name == "LiSPSM-DB") map = new osgShadow::LightSpacePerspectiveShadowMapDB;
        if (!map) return nullptr;
        map->setTextureSize(size);
        map->setLight(light);
        return map;
    }
    if (name == "PSSM") {
        osg::ref_ptr<osgShadow::ParallelSplitShadowMap> map =
            new osgShadow::ParallelSplitShadowMap(nullptr, 3);
        map->setTextureResolution(static_cast<unsigned>(mapSize));
        map->setAmbientBias(osg::Vec2(0.0f, 1.0f));
        map->setUserLight(light);
        return map;
    }
    if (name.rfind("VDSM-", 0) == 0) {
        const bool perspective = name.rfind("VDSM-persp-", 0) == 0;
        const int maps = name.back() - '0';
        if (name != (perspective ? "VDSM-persp-" : "VDSM-ortho-") + std::to_string(maps) || maps < 1 ||
            maps > 2)
            return nullptr;
        osgShadow::ShadowSettings* settings = scene.getShadowSettings();
        settings->setShadowMapProjectionHint(perspective
                                                 ? osgShadow::ShadowSettings::PERSPECTIVE_SHADOW_MAP
                                                 : osgShadow::ShadowSettings::ORTHOGRAPHIC_SHADOW_MAP);
        settings->setNumShadowMapsPerLight(static_cast<unsigned>(maps));
        settings->setTextureSize(size);
        settings->setLightNum(light->getLightNum());
        return new osgShadow::ViewDependentShadowMap;
    }
    return nullptr;
}

// The sizes of the depth textures the technique made, found by asking GL about every texture name up to
// the first unused run of them: the pbuffer has no depth texture of its own, so these are the shadow maps.
// What the technique did with the requested size, not what it was told.
std::vector<std::pair<int, int>> shadowMapSizes() {
    std::vector<std::pair<int, int>> sizes;
    GLint bound = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    for (GLuint name = 1, unused = 0; unused < 64; ++name) {
        if (!glIsTexture(name)) {
            ++unused;
            continue;
        }
        unused = 0;
        glBindTexture(GL_TEXTURE_2D, name);
        if (glGetError() != GL_NO_ERROR) continue;  // not a 2D texture
        GLint width = 0, height = 0, format = 0;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &height);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
        const bool depth = format == GL_DEPTH_COMPONENT || format == GL_DEPTH_COMPONENT16 ||
                           format == GL_DEPTH_COMPONENT24 || format == GL_DEPTH_COMPONENT32 ||
                           format == 0x8CAC /* GL_DEPTH_COMPONENT32F */;
        if (depth && width > 0) sizes.emplace_back(width, height);
    }
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(bound));
    return sizes;
}

}  // namespace

// [SECTION] Frames

int main(int argc, char** argv) {
    Options options;
    std::string error;
    if (argc == 3 && std::strcmp(argv[1], "--technique") == 0 && std::strcmp(argv[2], "list") == 0) {
        for (const std::string& name : techniqueNames()) std::cout << name << "\n";
        return 0;
    }
    if (!parseOptions(argc, argv, options, error)) {
        std::cerr << "shadowfx-osg-peer: " << error << "\n" << kUsage;
        return 2;
    }
    // A failed run must not leave a frame behind that looks like a success.
    std::remove(options.visibilityPath.c_str());
    std::remove(options.jsonPath.c_str());

    fx::DiagnosticList diagnostics;
    std::optional<runtime::Scene> scene;
    // The cameras whose frames are written: the scene's, or each camera of a stress case's path (its
    // temporal cases are scored frame by frame, for shimmer).
    std::vector<runtime::Camera> cameras;
    if (!options.stressCase.empty()) {
        std::optional<runtime::StressCase> stressCase = runtime::makeStressCase(options.stressCase);
        if (!stressCase) {
            std::cerr << "shadowfx-osg-peer: no stress case '" << options.stressCase << "'\n";
            return 2;
        }
        scene = std::move(stressCase->scene);
        cameras = std::move(stressCase->cameraPath);
    } else {
        scene = runtime::loadScene(options.scene, diagnostics);
    }
    if (!scene || diagnostics.errorCount() > 0) {
        std::cerr << diagnostics.str() << "shadowfx-osg-peer: cannot load scene '" << options.scene << "'\n";
        return 1;
    }
    if (cameras.empty()) cameras.push_back(scene->camera);
    runtime::Light light = shadowLight(*scene) ? *shadowLight(*scene) : runtime::Light{};
    if (!shadowLight(*scene)) {
        std::cerr << "shadowfx-osg-peer: scene '" << scene->name << "' has no light\n";
        return 1;
    }
    if (options.overrideDirection && light.type == runtime::Light::Type::Directional)
        light.direction = options.lightDirection;

    EglPbuffer pbuffer;
    if (!pbuffer.create(options.width, options.height, error)) {
        std::cerr << "shadowfx-osg-peer: " << error << "\n";
        return 1;
    }

    osg::ref_ptr<osgShadow::ShadowedScene> shadowed = new osgShadow::ShadowedScene;
    shadowed->getShadowSettings()->setReceivesShadowTraversalMask(kReceivesMask);
    shadowed->getShadowSettings()->setCastsShadowTraversalMask(kCastsMask);
    // RELATIVE_RF: the light's position is in the world (ABSOLUTE_RF would put it in eye space).
    osg::ref_ptr<osg::Light> osgLight = new osg::Light(0);
    if (light.type == runtime::Light::Type::Directional) {
        const osg::Vec3 toLight = -mirrored(light.direction);
        osgLight->setPosition(osg::Vec4(toLight, 0.0f));
    } else {
        osgLight->setPosition(osg::Vec4(mirrored(light.position), 1.0f));
        osgLight->setSpotCutoff(
            light.type == runtime::Light::Type::Spot ? glm::degrees(light.spotAngle) * 0.5f : 180.0f);
    }
    osgLight->setDirection(mirrored(light.direction));  // what ParallelSplitShadowMap reads
    osgLight->setAmbient(osg::Vec4(0, 0, 0, 1));
    osgLight->setDiffuse(osg::Vec4(1, 1, 1, 1));
    osgLight->setSpecular(osg::Vec4(0, 0, 0, 1));
    osg::ref_ptr<osg::LightSource> lightSource = new osg::LightSource;
    lightSource->setLight(osgLight);
    lightSource->setReferenceFrame(osg::LightSource::RELATIVE_RF);
    shadowed->addChild(lightSource);

    std::map<const runtime::Mesh*, osg::ref_ptr<osg::Geometry>> meshes;
    size_t triangles = 0;
    for (const runtime::SceneObject& object : scene->objects) {
        if (!object.mesh) continue;
        shadowed->addChild(buildObject(object, light, meshes));
        triangles += object.mesh->triangleCount();
    }

    osg::StateSet* state = shadowed->getOrCreateStateSet();
    state->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
    osg::ref_ptr<osg::LightModel> lightModel = new osg::LightModel;
    lightModel->setAmbientIntensity(osg::Vec4(0, 0, 0, 1));
    state->setAttributeAndModes(lightModel);
    osg::ref_ptr<osg::Material> material = new osg::Material;
    material->setColorMode(osg::Material::OFF);
    material->setAmbient(osg::Material::FRONT_AND_BACK, osg::Vec4(0, 0, 0, 1));
    material->setEmission(osg::Material::FRONT_AND_BACK, osg::Vec4(0, 0, 0, 1));
    material->setSpecular(osg::Material::FRONT_AND_BACK, osg::Vec4(0, 0, 0, 1));
    material->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(1e6f, 1e6f, 1e6f, 1));
    state->setAttribute(material);
    // The base texture the shaders multiply by: white, NEAREST and REPEAT (a default texture read with
    // CLAMP and LINEAR would blend in its border colour).
    osg::ref_ptr<osg::Image> white = new osg::Image;
    white->allocateImage(1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    std::memset(white->data(), 0xff, 4);
    osg::ref_ptr<osg::Texture2D> whiteTexture = new osg::Texture2D(white);
    whiteTexture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    whiteTexture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    whiteTexture->setWrap(osg::Texture::WRAP_S, osg::Texture::REPEAT);
    whiteTexture->setWrap(osg::Texture::WRAP_T, osg::Texture::REPEAT);
    state->setTextureAttributeAndModes(0, whiteTexture);

    osg::ref_ptr<osgShadow::ShadowTechnique> technique =
        makeTechnique(options.technique, options.mapSize, *shadowed, osgLight.get());
    if (!technique) {
        std::cerr << "shadowfx-osg-peer: unknown technique '" << options.technique << "'\n" << kUsage;
        return 2;
    }
    shadowed->setShadowTechnique(technique);

    osgViewer::Viewer viewer;
    viewer.setThreadingModel(osgViewer::Viewer::SingleThreaded);
    viewer.setUpViewerAsEmbeddedInWindow(0, 0, options.width, options.height);
    viewer.setLightingMode(osg::View::NO_LIGHT);  // no headlight
    viewer.setSceneData(shadowed);
    osg::Camera* camera = viewer.getCamera();
    camera->setClearColor(osg::Vec4(0, 0, 0, 1));
    camera->setDrawBuffer(GL_BACK);  // a pbuffer has a back buffer only
    camera->setReadBuffer(GL_BACK);
    // The camera's view culls back faces, as the effects' scene passes and the ground truth's G-buffer do
    // (D3D's default CullMode = CCW; the triangles are reversed to GL's counter-clockwise front): a camera
    // inside a closed occluder sees the receivers beyond it, not its inner faces. On the camera rather than
    // the scene, whose state the map passes inherit: a technique's own map-pass setting (ShadowMap's
    // override, ViewDependentShadowMap's and LiSPSM's mode left off) is below the camera's and wins.
    camera->getOrCreateStateSet()->setAttributeAndModes(new osg::CullFace(osg::CullFace::BACK),
                                                        osg::StateAttribute::ON);
    const auto setCamera = [&](const runtime::Camera& eye) {
        // The up shadowfx's view matrix has (its second row): where the scene's up is parallel to the view
        // (a camera looking straight down), Camera::view() takes another axis, and so must OSG's look-at.
        const glm::mat4 view = eye.view();
        const glm::vec3 up(view[0][1], view[1][1], view[2][1]);
        camera->setViewMatrixAsLookAt(mirrored(eye.position), mirrored(eye.target), mirrored(up));
        // The scene's near and far planes, as shadowfx's camera has them: OSG would otherwise compute its
        // own from the bounds, draw what lies beyond the far plane and fit its view-dependent maps to that
        // depth.
        camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
        camera->setProjectionMatrixAsPerspective(glm::degrees(eye.fovY),
                                                 static_cast<double>(options.width) / options.height,
                                                 eye.nearPlane, eye.farPlane);
    };
    setCamera(cameras.front());
    viewer.realize();

    // Binary PGM: what `bench` and `stress` read back without an image library; one frame per camera.
    std::ofstream visibility(options.visibilityPath, std::ios::binary);
    visibility << "P5\n"
               << options.width << " " << options.height * static_cast<int>(cameras.size()) << "\n255\n";
    using Clock = std::chrono::steady_clock;
    std::vector<double> frameMs;
    std::vector<uint8_t> rgba(static_cast<size_t>(options.width) * options.height * 4);
    for (size_t view = 0; view < cameras.size(); ++view) {
        setCamera(cameras[view]);
        // The first camera's warm-up and timed frames; each later camera of a path is one timed frame.
        const int count = view == 0 ? options.warmup + options.frames : 1;
        for (int frame = 0; frame < count; ++frame) {
            const auto start = Clock::now();
            viewer.frame();
            glFinish();  // as bench's frames: until the GPU has finished
            const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
            if (view > 0 || frame >= options.warmup) frameMs.push_back(ms);
        }
        // The camera's last frame is its visibility frame: its red channel, rows bottom-up in GL, written
        // top-down.
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadBuffer(GL_BACK);
        glReadPixels(0, 0, options.width, options.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        if (glGetError() != GL_NO_ERROR) {
            visibility.close();
            std::remove(options.visibilityPath.c_str());
            std::cerr << "shadowfx-osg-peer: reading the frame back failed\n";
            return 1;
        }
        for (int y = options.height - 1; y >= 0; --y)
            for (int x = 0; x < options.width; ++x)
                visibility.put(static_cast<char>(rgba[(static_cast<size_t>(y) * options.width + x) * 4]));
    }
    visibility.close();
    if (!visibility) {
        std::remove(options.visibilityPath.c_str());
        std::cerr << "shadowfx-osg-peer: cannot write " << options.visibilityPath << "\n";
        return 1;
    }
    // Honoured: it made shadow maps, each of the requested size (PSSM's splits and VDSM's maps are each
    // one texture of that size).
    const std::vector<std::pair<int, int>> mapSizes = shadowMapSizes();
    const bool honoured =
        !mapSizes.empty() && std::all_of(mapSizes.begin(), mapSizes.end(), [&](const std::pair<int, int>& s) {
            return s.first == options.mapSize && s.second == options.mapSize;
        });
    nlohmann::ordered_json record{{"peer", "osg/" + options.technique},
                                  {"technique", options.technique},
                                  {"scene", scene->name},
                                  {"map_size", options.mapSize},
                                  {"shadow_map_sizes", mapSizes},
                                  {"map_size_honoured", honoured},
                                  {"width", options.width},
                                  {"height", options.height},
                                  {"gl_renderer", reinterpret_cast<const char*>(glGetString(GL_RENDERER))},
                                  {"gl_version", reinterpret_cast<const char*>(glGetString(GL_VERSION))},
                                  {"osg_version", osgGetVersion()},
                                  {"triangles", triangles},
                                  {"warmup_frames", options.warmup},
                                  {"frame_ms", frameMs}};
    std::ofstream json(options.jsonPath);
    json << record.dump(2) << "\n";
    if (!json) {
        std::cerr << "shadowfx-osg-peer: cannot write " << options.jsonPath << "\n";
        return 1;
    }
    return 0;
}
