// EffectRenderer: runs a compiled effect on OpenGL. It links one GL program per pass, creates the
// effect's textures, samplers and render targets, binds semantics (runtime/render/src/SemanticBinder.h) and
// executes the SAS scripts (runtime/render/src/ScriptInterpreter.cpp) to render frames of a scene.
//
// Needs a current GL 4.5 context (runtime/GlContext.h) for its whole life.
#pragma once

#include <fx/CompiledEffect.h>
#include <fx/Diagnostics.h>
#include <fx/HostFile.h>
#include <runtime/EffectPass.h>
#include <runtime/EffectPool.h>
#include <runtime/EffectVariable.h>
#include <runtime/FrameImage.h>
#include <runtime/FrameStats.h>
#include <runtime/LightParameterization.h>
#include <runtime/Scene.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace runtime {

struct FrameOptions {
    int width = 640;
    int height = 480;
    std::string technique;  // "" = the STANDARDSGLOBAL script's choice, else the first technique
    float time = 0.0f;      // seconds, for the Time semantic
    // Time every pass (GL_TIME_ELAPSED queries and CPU clocks) into FrameStats::passTimings and the
    // runtime's own CPU time into FrameStats::cpu. render() then waits for the GPU to finish the frame, so
    // its wall time is the frame's; normal renders leave it off and pay for no queries.
    bool timePasses = false;
    // Leave out what the scene does not need (docs/measurement.md, "Leave-out"): draws culled per pass
    // through a BVH (camera passes to the view frustum, light passes to the casters whose shadow can reach
    // what the camera sees), passes whose writes nobody reads, light passes whose targets would come out as
    // last frame's, per-frame semantics bound per pass instead of per draw. The image is the same either way.
    bool leaveOut = true;
    // With leaveOut: keep render targets whose contents would come out as last frame's (leave-out's cached
    // passes). False redraws them as if the light or the objects had moved: every pass runs, culling and
    // dead-pass removal still apply. What `bench` times as a technique's full cost.
    bool reuseTargets = true;
    // Count the fragments each pass writes (GL_SAMPLES_PASSED queries) into PassStats::texelsWritten;
    // clears count their targets' texels either way.
    bool countTexels = false;
    // Draw passes that write no colour (ColorWriteEnable = 0 on every bound target) into their depth-stencil
    // target alone and without a pixel shader where it has no side effect (PassStats::depthOnlyDraws). The
    // image is the same either way; off draws them as D3D9 states them (for comparison).
    bool depthOnlyPasses = true;
    // With leaveOut: draw the objects of a Draw=Geometry that share a mesh as one instanced draw, their
    // per-object values (World and what derives from it, the object's colour and id, compile arguments
    // computed from them) read from a buffer by instance (fx/InstancedPass.h). Passes the instanced
    // variant cannot express are drawn object by object. The image is the same either way; off draws
    // every object alone (for comparison).
    bool batching = true;
    // Render targets the caller reads after the frame (readTarget): outputs like the frame's colour, so
    // leave-out keeps the passes that write them.
    std::vector<std::string> outputTargets;
};

// Texels for EffectRenderer::setTexture: RGBA floats, top row first, layer after layer: a cube's six faces
// (+X -X +Y -Y +Z -Z), an array's elements, a cube array's cubes (each six faces) in turn.
struct TextureData {
    int width = 0;
    int height = 1;
    int elements = 1;  // an array's elements (cubes for a TextureCubeArray); 1 for other textures
    std::vector<float> rgba;
};

class EffectResources;  // opaque: what the renderer owns (runtime/render/src/EffectResources.h)
class HostFrame;        // opaque: the frame of a host file (runtime/render/src/HostFrame.h)

class EffectRenderer {
public:
    // Links every pass's program, creates textures and samplers. Returns nullptr if a program does not
    // link or a resource cannot be created; the diagnostics say why.
    // With a `pool` (runtime/EffectPool.h), the effect's `shared` parameters share their values with the
    // other effects created in it; nullptr, with a diagnostic, where the pool holds one with another type.
    static std::unique_ptr<EffectRenderer> create(std::shared_ptr<const fx::CompiledEffect> effect,
                                                  fx::DiagnosticSink& diagnostics,
                                                  std::shared_ptr<EffectPool> pool = nullptr);
    // The same from a compiled effect file (`shadowfx compile EFFECT.fx --out EFFECT.sfxo`), which needs
    // no compiler: a file that is not one, or is truncated, corrupt or of another format version, is an
    // error at `path` (fx/CompiledEffectFile.h). Source files load through runtime/ReloadableEffect.h or
    // fx/EffectFile.h, which link the compiler.
    static std::unique_ptr<EffectRenderer> createFromFile(const std::string& path,
                                                          fx::DiagnosticSink& diagnostics,
                                                          std::shared_ptr<EffectPool> pool = nullptr);
    ~EffectRenderer();
    // The semantics the runtime gives parameters values by (case-insensitive): the matrices with their
    // Inverse/Transpose/InverseTranspose forms, camera, light, object and scene values, the light fits'
    // tunables, and STANDARDSGLOBAL (the script parameter). create() warns of a numeric parameter whose
    // semantic is none of them: it keeps its default value.
    static std::vector<std::string> boundSemantics();
    EffectRenderer(const EffectRenderer&) = delete;
    EffectRenderer& operator=(const EffectRenderer&) = delete;

    const fx::CompiledEffect& effect() const;

    // Parameters, by name. A parameter set here is pinned: semantics no longer overwrite it.
    std::optional<size_t> findParameter(std::string_view name) const;
    const fx::Value& parameter(size_t index) const;
    void setParameter(size_t index, const fx::Value& value);
    // True once setParameter() set it: what hot reload carries over to the next effect.
    bool isPinned(size_t index) const;
    // Parses VALUE for the parameter's type ("0.5", "true", "1,0,0", "{1, 0, 0}") and sets it.
    bool setParameterFromText(std::string_view name, std::string_view text, fx::DiagnosticSink& diagnostics);
    // Gives a texture parameter that is not a render target the application's texels (replacing its file
    // or default), as a texture of the parameter's type: Texture2D, TextureCube, Texture1DArray (height
    // 1), Texture2DArray, TextureCubeArray; mip levels as the effect declares them (generated). False,
    // with a diagnostic, for another parameter or texels that do not fill width x height x layers.
    bool setTexture(size_t index, const TextureData& data, fx::DiagnosticSink& diagnostics);
    // Gives a D3D10 buffer parameter its contents: `elements` elements of `elementBytes` each, laid out as
    // D3D lays them out (Buffer<T>: T's components as 32-bit values; StructuredBuffer<T>: T packed with
    // 4-byte alignment, as FX11 applications fill them; ByteAddressBuffer: raw bytes, elementBytes 4 per
    // word). Until set, a buffer reads as zeros, as an unbound D3D10 resource does. False, with a
    // diagnostic, for another parameter or an element size that is not the type's.
    bool setBuffer(size_t index, const void* bytes, size_t elements, size_t elementBytes,
                   fx::DiagnosticSink& diagnostics);

    // [SECTION] The application drives the passes (runtime/EffectPass.h, docs/api.md). Lookups return
    // invalid handles for what the effect does not have.
    size_t techniqueCount() const;
    EffectTechnique technique(size_t index);
    // By name; a technique in a D3D11 fxgroup also by "group.name".
    EffectTechnique technique(std::string_view name);
    // D3DX9's ValidateTechnique, by name: valid if the effect has it ready to apply; otherwise why not
    // (what left it out, as its warning said; or that no technique has that name).
    TechniqueValidation validateTechnique(std::string_view name) const;
    size_t variableCount() const;
    EffectVariable variable(size_t index);
    EffectVariable variable(std::string_view name);  // case-sensitive, as HLSL names are
    // The first parameter declared with `semantic`, case-blind as D3DX's GetParameterBySemantic.
    EffectVariable variableBySemantic(std::string_view semantic);

    // [SECTION] Host files (fx/HostFile.h, runtime/HostFileReader.h, docs/host-files.md)
    // For an effect written for an application, without SAS scripts: render() then draws the frame the
    // host file describes (its targets, its parameters' values, its steps) through the pass API, as that
    // application drew it, instead of running the SAS host; FrameOptions::technique is not used. False,
    // with diagnostics at the file's lines, where it names what the effect does not have (nothing is set
    // then). nullptr goes back to the SAS host.
    bool setHostFile(std::shared_ptr<const fx::HostFile> host, fx::DiagnosticSink& diagnostics);

    // Makes the next render() a reset frame, as FX Composer's Reset made one: parameters with the
    // FXCOMPOSER_RESETPULSE semantic read true in it and false in the frames after (effects clear what
    // they accumulate over frames then), and the host clears the frame before a scene effect, which it
    // otherwise hands the frame as the effect left it (docs/fxcomposer.md). The first frame after create()
    // is a reset frame too, and so is one that runs another technique than the frame before; a frame of
    // another size than the one before also starts on the background.
    void reset();

    // Renders one frame of `scene`. Returns false (with diagnostics) if the technique does not exist or a
    // GL error occurred.
    bool render(const Scene& scene, const FrameOptions& options, fx::DiagnosticSink& diagnostics,
                FrameStats* stats = nullptr);

    // The matrices light `lightName` renders with in this effect (the Parameterization annotation of its
    // light matrices, docs/techniques/light-space-parameterizations.md) for `scene` in a frame of `options`'
    // size: what RenderPort=lightN and the annotated parameters get. nullopt if the scene has no such light.
    // A fit to what the camera sees (LightFitVisibleSamples) runs its own pre-pass of `scene` at `options`'
    // size (GL work: call it where render() could be called).
    std::optional<LightFit> lightFit(const Scene& scene, std::string_view lightName,
                                     const FrameOptions& options) const;

    // The frame's colour target as rendered by the last render().
    FrameImage readFrame() const;
    // Copies the last render()'s colour into `framebuffer` (a GL framebuffer object of the caller's, or 0
    // for a window's default framebuffer) at (0, 0) at the frame's size, without reading it back: how an
    // application shows or composes the frame. Rows keep the runtime's order (row 0 at the top, as with
    // glClipControl(GL_UPPER_LEFT)). Leaves `framebuffer` bound; false if there is no frame yet.
    bool blitFrameTo(uint32_t framebuffer) const;
    // A texture's first channels as floats (rows top to bottom) at mip `level`, for tests and debugging
    // views; nullopt if the parameter is not an allocated texture or has no such level.
    std::optional<std::vector<float>> readTarget(std::string_view textureName, int* width, int* height,
                                                 int* channels, int level = 0) const;
    // The same into `texels`, whose allocation is reused where large enough (a scan over every texture
    // reads them all through one buffer); false where the other gives nullopt.
    bool readTarget(std::string_view textureName, std::vector<float>& texels, int* width, int* height,
                    int* channels, int level = 0) const;

private:
    explicit EffectRenderer(std::unique_ptr<EffectResources> resources);
    std::unique_ptr<EffectResources> mImpl;
    std::unique_ptr<HostFrame> mHostFrame;
};

// Writes `image` as a PNG; false (with a message in `error`) on failure.
bool writePng(const FrameImage& image, const std::string& path, std::string& error);

}  // namespace runtime
