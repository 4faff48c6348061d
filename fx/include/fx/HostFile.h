// HostFile: what an application did around an effect written for it, with no SAS script: the render
// targets it created, the values it gave the parameters and the frame it drew (which techniques and passes,
// in which order, into which targets, with which clears, from whose point of view). docs/host-files.md
// describes the JSON format, which runtime/HostFileReader.h reads; runtime::EffectRenderer::setHostFile
// makes render(Scene) draw that frame through the pass API (runtime/EffectPass.h), as the application
// would. Part of the contract: data and a check against a compiled effect, no JSON and no GL.
#pragma once

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fx {

// A render target the application created: a colour texture with a depth buffer of its own. A cube, an
// array or a volume is bound whole, as D3D10's view of the whole resource: a geometry shader's
// SV_RenderTargetArrayIndex chooses the face, element or slice each primitive is drawn into, and its depth
// buffer has as many layers.
struct HostTarget {
    enum class Kind { Plane, Cube, Array, Volume };
    std::string name;
    fx::TextureFormat format = fx::TextureFormat::RGBA8;
    Kind kind = Kind::Plane;
    int layers = 1;  // an array's elements, a volume's slices
    int width = 0;   // 0 x 0: the frame's size (a cube's faces: the frame's height square)
    int height = 0;
    std::string texture;  // the texture parameter it is given to ("" = none)
    fx::SourceLoc loc;
};

// One factor of a matrix product: a matrix of the object, the camera, a light or the step's render port.
struct HostMatrix {
    enum class Space { Port, Camera, Light };
    enum class Kind { World, View, Projection, WorldView, ViewProjection, WorldViewProjection };
    Space space = Space::Port;
    std::string light;  // Space::Light
    Kind kind = Kind::World;
    bool inverse = false;
    bool transpose = false;
};

// What a parameter is; its value is computed for each step (and each object where it depends on one).
struct HostValue {
    enum class Kind {
        Constant,       // numbers, set once
        Matrix,         // a product of HostMatrix factors, in D3D's row-vector order
        LightPosition,  // a light's position (world space, or the camera's view space)
        LightDirection,
        LightColor,
        LightCosHalfAngle,  // cos(spot angle / 2)
        ObjectColor,        // the object's colour, alpha 1
        ViewportSize,       // the step's target size in pixels
    };
    Kind kind = Kind::Constant;
    std::vector<float> numbers;       // Constant
    std::vector<HostMatrix> factors;  // Matrix
    std::string light;                // Light*
    bool cameraViewSpace = false;     // LightPosition, LightDirection
    bool perObject() const;           // depends on the object drawn
};

struct HostParameter {
    std::string name;
    HostValue value;
    fx::SourceLoc loc;
};

// A light's projection as the application made it (D3DXMatrixPerspectiveFovLH with aspect 1), in place
// of the fit to the scene's bounds that RenderPort=lightN gets; the view stays the light's.
struct HostLightProjection {
    std::string light;
    float fovY = 90.0f;  // degrees
    float nearPlane = 0.1f;
    float farPlane = 100.0f;
    fx::SourceLoc loc;
};

// One viewport, as D3D10's D3D10_VIEWPORT with its default depth range (0 to 1): a rectangle in pixels from
// the target's upper-left corner.
struct Viewport {
    float x = 0.0f;
    float y = 0.0f;
    float width = 0.0f;
    float height = 0.0f;
};

// One step of the frame: a technique's passes (or one of them) drawn into a target.
struct HostStep {
    std::string technique;
    std::string pass;    // "" = every pass in order
    std::string target;  // a HostTarget's name, or "frame"
    std::string port;    // "camera" or a light's name: whose View and Projection
    std::optional<std::array<float, 4>> clearColor;
    std::optional<float> clearDepth;
    enum class Draw { Geometry, Quad, Nothing };
    Draw draw = Draw::Geometry;
    // The application's RSSetViewports: viewport i is the one a geometry shader's SV_ViewportArrayIndex i
    // selects. Empty: one viewport, the whole target.
    std::vector<Viewport> viewports;
    // FX11's Dispatch after Apply, for the step's passes that set a compute shader: each term a group count
    // or a parameter whose components are counts (as a script's Dispatch=x,y,z); missing counts are 1.
    // Empty: the step dispatches nothing.
    struct DispatchTerm {
        std::string parameter;  // "" = `count`
        uint32_t count = 1;
    };
    std::vector<DispatchTerm> dispatch;
    fx::SourceLoc loc;
};

// How the frame's colour becomes the shadow factor that bench and check score, for an effect that has no
// SHADOWFX_VISIBILITY hook of its own (docs/host-files.md, "Scoring").
struct HostVisibility {
    std::vector<HostParameter> set;       // constants for the scored frames
    std::vector<std::string> unshadowed;  // targets that, cleared and left undrawn, light everything
    fx::SourceLoc loc;
};

struct HostFile {
    std::string path;
    std::vector<HostTarget> targets;
    std::vector<HostParameter> parameters;
    std::vector<HostLightProjection> lights;
    std::vector<HostStep> frame;
    std::optional<HostVisibility> visibility;

    const HostTarget* findTarget(const std::string& name) const;
};

// "2d", "cube", "array", "volume": how a host file spells a target's kind.
std::string_view hostTargetKindName(HostTarget::Kind kind);

// Checks the file against an effect: every technique, pass, parameter and texture it names exists and
// every value fits its parameter's type. False, with the problems at the host file's lines, otherwise.
bool checkHostFile(const HostFile& host, const fx::CompiledEffect& effect, fx::DiagnosticSink& diagnostics);

}  // namespace fx
