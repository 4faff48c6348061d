// CompiledEffect: what the effect compiler hands the runtime. Per technique and pass: GLSL for each stage
// with reflection (which uniform-block member, sampler and vertex input is which effect parameter,
// compile argument or semantic), the pass's render states and its SAS script; per effect: initial
// parameter values, textures and samplers. No OpenGL here: the runtime turns this into GL objects.
#pragma once

#include <fx/ParameterSemantics.h>
#include <fx/PreshaderProgram.h>
#include <fx/RefusedTechnique.h>
#include <fx/RenderStates.h>
#include <fx/SasScript.h>
#include <fx/Value.h>
#include <fx/VertexStreams.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fx {

// An annotation (`<float UIMin = 0.0;>`) as a value: its literal evaluated at compile time and converted
// to its declared type (Value::type), so that tools and the application's handles read no syntax tree.
// One whose literal does not evaluate is left out (the compiler reported it).
struct AnnotationValue {
    std::string name;  // as written; looked up case-blind
    Value value;
};
using Annotations = std::vector<AnnotationValue>;
// Case-blind, as D3DX's GetAnnotationByName; nullptr when missing.
const AnnotationValue* findAnnotation(const Annotations& annotations, std::string_view name);

// Hull and Domain are D3D11's names for GL's tessellation control and evaluation stages. Compute runs
// alone in its pass (SetComputeShader), dispatched instead of drawn.
enum class ShaderStage { Vertex, Fragment, Geometry, Hull, Domain, Compute };
// The stage as the effect's author names it: "vertex", "pixel", "geometry", "hull", "domain", "compute".
std::string_view shaderStageName(ShaderStage stage);

// A numeric member of a struct parameter as its uniform block stores it: the part of the parameter's value
// (Value::data from `firstComponent`, `type.componentCount()` numbers) that goes to `offset` bytes past the
// block member, laid out as UniformBinding lays out a parameter.
struct UniformField {
    std::string path;  // the member after the parameter's name: ".color", "[1].lights[0].position"
    TypeDesc type;     // numeric
    uint32_t firstComponent = 0;
    uint32_t offset = 0;  // from the block member's offset
    uint32_t arrayStride = 0;
    uint32_t matrixStride = 0;
    bool hlslColumnsContiguous = true;
};

// One member of a stage's uniform block (std140; offsets and strides from SPIRV-Cross reflection).
struct UniformBinding {
    enum class Source { Parameter, CompileArgument };
    std::string name;  // the member's name in the block
    Source source = Source::Parameter;
    size_t index = 0;     // CompiledEffect::parameters index, or CompiledPass::arguments index
    TypeDesc type;        // HLSL type of the member
    uint32_t offset = 0;  // byte offset in the block
    uint32_t size = 0;    // bytes the member occupies in the block
    uint32_t arrayStride = 0;
    uint32_t matrixStride = 0;
    // How the GLSL block stores a matrix: true if each HLSL *column* is contiguous (the usual case for
    // HLSL's default column_major packing), false if each HLSL row is. The runtime packs Value::data
    // (HLSL rows) accordingly.
    bool hlslColumnsContiguous = true;
    // False if the stage's code never reads the member (glslang keeps every global in the block): the
    // runtime neither packs nor binds it (SPIRV-Cross's active buffer ranges).
    bool active = true;
    // A struct parameter (or an array of them): where the block holds each number of its value, one field
    // per numeric member of each element, nested structs and their arrays taken apart. Empty elsewhere.
    std::vector<UniformField> fields;
};

// SamplerBinding::samplerParameter of a texture read without a sampler (Texture2D.Load).
inline constexpr size_t kNoSampler = static_cast<size_t>(-1);

struct SamplerBinding {
    std::string glslName;         // the sampler uniform in the GLSL
    int unit = 0;                 // texture unit, declared in the GLSL (layout(binding))
    size_t samplerParameter = 0;  // CompiledEffect::parameters index of the effect's sampler
    bool depthCompare = false;    // a sampler2DShadow: the bound texture must compare
    // Whether the stage's code reads it, from its SPIR-V (the variables its entry point reaches): glslang
    // keeps every sampler the effect declares in every stage, read or not, and SPIRV-Cross declares them.
    bool read = true;
    // D3D10's separate textures and samplers: GL's combined sampler for one (Texture2D, SamplerState)
    // pair the code samples with. The texture bound is `textureParameter`, not the sampler's own
    // (SamplerDesc::texture); the unit is the pass's (assigned after both stages compiled, then written
    // into each stage's GLSL).
    std::string pairTexture;  // the effect's texture and sampler names ("" if not a pair)
    std::string pairSampler;
    std::optional<size_t> textureParameter;  // CompiledEffect::parameters index of pairTexture
    // A D3D9 pass's states of the sampler register this sampler is bound to (`MinFilter[0] = LINEAR;`,
    // `Sampler[0] = (s);`): the states the sampler has in this pass, CompiledEffect::passSamplers' index
    // (-1: the sampler's own, SamplerDesc). `Texture[0] = <t>;` sets `textureParameter`.
    int passSampler = -1;
    // A full-screen pass's sampler (a D3D9 pixel shader alone, or a vertex shader that passes the position
    // through: fx/src/PositionPassThrough.h) that the effect gives no texture: no file,
    // no render target, no texture function. What its application bound there was the scene it had
    // rendered (a post-processing pass, a SpriteBatch sprite), so a host that draws the pass binds its own
    // picture of the scene unless the application gave the texture (docs/fixed-function.md).
    bool hostPicture = false;
};

// A D3D10 StructuredBuffer<T> or ByteAddressBuffer a stage reads: a GL shader storage block (std430).
// The application writes elements as D3D packs them (members 4-byte aligned, no padding); the runtime
// copies each run of a member's bytes to where the GL block has it.
struct StorageBufferBinding {
    struct Run {
        uint32_t d3dOffset = 0;  // within a D3D element
        uint32_t glOffset = 0;   // within a GL element
        uint32_t bytes = 0;
    };
    std::string glslName;  // the GLSL block (the parameter's name)
    size_t parameter = 0;  // CompiledEffect::parameters index
    // The block's GL_SHADER_STORAGE_BUFFER binding point, fixed in its GLSL by the parameter's place
    // among the effect's storage-block parameters (docs/d3d10.md): the runtime binds the parameter's buffer
    // there, never looks a block up by name (two buffers of one element type share one SPIR-V block type,
    // whose GLSL names are not theirs).
    int binding = 0;
    uint32_t glStride = 0;   // bytes per element in the GL block
    uint32_t d3dStride = 0;  // bytes per element as D3D packs it
    std::vector<Run> runs;   // in D3D order, covering the element
    // The binding point of the block of the buffer's hidden counter (AppendStructuredBuffer,
    // ConsumeStructuredBuffer, a RWStructuredBuffer's IncrementCounter): one uint the runtime keeps with the
    // buffer; -1 without one.
    int counterBinding = -1;
};

// A D3D11 RWTexture1D/2D/3D/2DArray<T> or RWBuffer<T> a stage reads or writes: a GL image (image load/store).
// The runtime binds the parameter's texture at `unit`, with the format the GLSL declares, which glslang
// takes from T (docs/d3d10.md, "Compute shaders and read-write resources").
struct ImageBinding {
    std::string glslName;  // the image uniform (the parameter's name)
    size_t parameter = 0;  // CompiledEffect::parameters index
    std::string format;    // GLSL's format qualifier: "rgba32f", "r32f", "rgba8", "r32ui", ...
    // The image unit: the parameter's place among the pass's image parameters in ascending order (the same
    // in every stage of the pass), declared in the GLSL (layout(binding)).
    int unit = 0;
};

// A vertex shader input at its attribute location: the runtime feeds it the mesh stream the compiler chose
// (fx/VertexStreams.h, whatever name the effect gave the input), or a defined default where the mesh has
// no such stream.
struct VertexInput {
    std::string semantic;  // the stream's D3D9 name, index included ("TEXCOORD0"), for readers of the GLSL
    int location = 0;
    int components = 4;
    VertexStreamSlot stream;
};

// What a stage's code does besides computing its outputs, read by the compiler from its SPIR-V: the
// program state the runtime enables for it, and whether a pass that writes no colour may leave its pixel
// stage out (GpuProgram::pixelShaderHasSideEffects).
struct StageEffects {
    bool discards = false;          // clip(), texkill, an alpha test written as clip (OpKill)
    bool writesDepth = false;       // SV_Depth (gl_FragDepth)
    bool writesSampleMask = false;  // SV_Coverage (gl_SampleMask)
    bool writesImages = false;      // stores to a read-write texture (imageStore)
    bool writesBuffers = false;     // declares a storage buffer it may write (RWStructuredBuffer, ...)
    bool atomics = false;           // Interlocked* on an image, a buffer or groupshared memory
    bool writesPointSize = false;   // PSIZE (gl_PointSize)
    bool writesDiffuse = false;     // the COLOR0 varying, what a fixed-function pixel stage outputs
    int clipDistances = 0;          // SV_ClipDistance: the gl_ClipDistance entries it writes, 0 to 8
};

struct StageProgram {
    ShaderStage stage = ShaderStage::Vertex;
    std::string entryPoint;        // the user's function
    std::string profile;           // "vs_3_0"
    std::string hlsl;              // the generated HLSL unit handed to glslang
    std::string glsl;              // GLSL 4.50 core from SPIRV-Cross
    std::string uniformBlockName;  // "" if the stage has no uniforms
    int uniformBlockBinding = -1;
    uint32_t uniformBlockSize = 0;
    std::vector<UniformBinding> uniforms;
    // D3D10 pairs, and Buffer<T> as a GL buffer texture: a SamplerBinding with pairTexture the buffer's
    // name and no sampler.
    std::vector<SamplerBinding> samplers;
    std::vector<StorageBufferBinding> storageBuffers;  // the runtime binds them per pass (PassBindings)
    std::vector<ImageBinding> images;                  // likewise
    std::vector<VertexInput> inputs;                   // vertex stage
    uint64_t sourceHash = 0;                           // hash of hlsl + options: the compile cache's key
    StageEffects effects;
};

// An argument of a compile expression bound to a `uniform` entry-point parameter; the runtime runs `value`
// (converting to `type`) when one of its inputs changed and stores it in the uniform block member that
// names it.
struct CompileArgument {
    PreshaderProgram value;
    TypeDesc type;
    std::string memberName;  // "fx_arg0", ...
};

struct RenderStateSetting {
    RenderStateId id;
    // The value, folded at compile time (enum names, literals, constant expressions), or, for an
    // expression that reads parameters, the program the runtime runs.
    std::optional<double> constant;
    PreshaderProgram value;  // empty when `constant` is set
    SourceLoc loc;
};

// `string LeaveOutWhen = "...";` on a pass: the scene condition under which the effect guarantees that
// later passes do not need what the pass writes (docs/measurement.md, "Leave-out").
enum class LeaveOutCondition {
    Never,
    NoClosedObjects,  // no object's mesh is closed: a second depth layer finds nothing
    NoLightArea,      // no light has an area: no soft-shadow filter needed
};

// D3D10's stream output (`ConstructGSWithSO`) as GL transform feedback: what the last stage before the
// rasterizer (the geometry shader, or the vertex shader a ConstructGSWithSO names) captures into the pass's
// buffers, resolved by the compiler from the declaration string (docs/d3d10.md, "Stream output").
struct StreamOutElement {
    std::string semantic;  // canonical, index included ("POSITION0", "TIMER0")
    int slot = 0;          // the output buffer (D3D10's slot 0..3)
    uint32_t offset = 0;   // bytes into the slot's vertex
    int components = 4;
    // How the shader writes it: a vertex attribute reading it back converts the same way.
    enum class Component { Float, Int, UInt };
    Component component = Component::Float;
};

struct StreamOutput {
    // The list glTransformFeedbackVaryings takes (GL_INTERLEAVED_ATTRIBS), in the declaration's order per
    // slot: the stage's outputs by their GLSL names, `gl_SkipComponentsN` for `$SKIP` and `gl_NextBuffer`
    // between slots.
    std::vector<std::string> varyings;
    std::vector<StreamOutElement> elements;  // what a pass drawing the capture reads, `$SKIP`s left out
    uint32_t strides[4] = {0, 0, 0, 0};      // bytes per vertex in each slot's buffer (0: slot unused)
    // What glBeginTransformFeedback is given: the geometry shader's stream type (PointStream, LineStream,
    // TriangleStream), or, for a vertex shader's output, the primitive the pass draws.
    enum class Primitive { Points, Lines, Triangles };
    Primitive primitive = Primitive::Points;
    // False where the pass's pixel shader is NULL: the runtime captures with GL_RASTERIZER_DISCARD.
    bool rasterizes = true;
    // `int StreamOutVertices = N;` on the pass: the vertices each buffer holds; a capture stops there.
    int capacity = 65536;
};

struct CompiledPass {
    std::string name;
    SourceLoc loc;
    // The pass annotations the runtime acts on, resolved here so that the runtime never looks a pass up
    // in the source (by name or by position: a technique compiled alone has other indices).
    // `bool CullClosedOnly = true;`: the pass's CullMode applies to closed meshes only, open ones are drawn
    // with culling off.
    bool cullClosedOnly = false;
    LeaveOutCondition leaveOutWhen = LeaveOutCondition::Never;
    // `float FilterReachTexels = N;`: how far around a receiver's texel the passes reading this pass's map
    // look (light-pass culling keeps every caster they can see); 0 = not declared, the runtime's default.
    float filterReachTexels = 0.0f;
    // `bool CastersOnly = true;`: a light pass draws the objects that cast shadows alone
    // (SceneObject::castsShadow); receivers only, such as a ground under a sun, stay out of its map.
    bool castersOnly = false;
    StageProgram vertex;
    StageProgram fragment;
    StageProgram geometry;  // D3D10's geometry shader (SetGeometryShader); empty glsl when the pass has none
    StageProgram hull;      // D3D11's hull shader (SetHullShader): GL's tessellation control stage
    StageProgram domain;    // D3D11's domain shader (SetDomainShader): GL's tessellation evaluation stage
    // D3D11's compute shader (SetComputeShader): a compute pass has no other stage; the application (the
    // pass API's dispatch()) or the pass's script (`Dispatch=x,y,z`) runs it instead of drawing.
    StageProgram compute;
    // With a hull shader: the control points of one patch (its InputPatch<T, n>), drawn as GL_PATCHES of
    // that many vertices; 0 draws triangle lists.
    int patchVertices = 0;
    // What the pass's draws give a geometry shader, by its input primitive: the meshes' triangles, their
    // vertices as points (`point`), their edges once each as lines (`line`), or their triangles with the
    // neighbours across each edge (`triangleadj`).
    enum class DrawPrimitive { Triangles, Points, Lines, TrianglesAdjacency };
    DrawPrimitive primitive = DrawPrimitive::Triangles;
    // Set where the pass's geometry shader is a ConstructGSWithSO: each draw captures into the pass's
    // buffers.
    std::optional<StreamOutput> streamOut;
    // `string DrawAuto = "pass";` (a stream-output pass of the same technique, this one included): the pass
    // draws what that pass captured last, as D3D10's DrawAuto, instead of the scene's meshes; its vertex
    // inputs read the capture's elements by semantic (vertex attribute k is element k). -1: meshes.
    int drawAuto = -1;
    std::vector<CompileArgument> arguments;
    std::vector<RenderStateSetting> states;  // in source order, shaders excluded
    bool hasScript = false;
    std::vector<ScriptCommand> script;  // the pass's Script annotation (no script: Draw=Geometry)
    Annotations annotations;            // every annotation of the pass, in source order
    // The parameters the pass reads, ascending, once each (EffectVariable::isUsed): a uniform-block member
    // its code reads (UniformBinding::active), a sampler or texture it samples, a storage buffer or image it
    // declares, an input of a state's or compile argument's program.
    std::vector<size_t> readParameters;
};

struct CompiledTechnique {
    std::string name;
    std::string group;  // the D3D11 `fxgroup` holding it ("" if none); findTechnique takes "group.name"
    SourceLoc loc;
    std::vector<CompiledPass> passes;
    bool hasScript = false;
    std::vector<ScriptCommand> script;  // the technique's Script annotation (no script: every pass in order)
    Annotations annotations;            // every annotation of the technique, in source order
};

enum class TextureFormat {
    RGBA8,
    RGBA16F,
    RGBA32F,
    R16F,
    R32F,
    RG16F,
    RG32F,
    RGBA16,  // 16-bit normalized channels (D3D9's A16B16G16R16): what quantized moment maps need
    D16,
    D24S8,
    D24X8,
    D32F,
};
bool isDepthFormat(TextureFormat format);
// D3D9 ("A8R8G8B8", "R32F", "G32R32F", "A16B16G16R16F", "D24S8", "D32F_LOCKABLE"), DXGI ("R32_FLOAT")
// and plain ("RGBA8", "RG32F") spellings, case-insensitive.
std::optional<TextureFormat> parseTextureFormat(std::string_view name);
std::string_view textureFormatName(TextureFormat format);

struct TextureDesc {
    enum class Kind {
        RenderColorTarget,         // semantic RENDERCOLORTARGET
        RenderDepthStencilTarget,  // semantic RENDERDEPTHSTENCILTARGET
        File,                      // ResourceName annotation (or a file name initializer)
        Runtime,     // other semantics: the application supplies it, or the runtime a neutral one
        Procedural,  // `string Procedural = "noise"`: white noise generated at effect creation (the only
                     // generator so far; runtime/render/include/private/runtime/ProceduralTexture.h)
        Function,    // `string function = "f"`: FX Composer's texture function, `fill` drawn into every
                     // texel of every level (and slice, or face) at effect creation
        Noise,       // semantic NOISE on a 2D texture nothing else fills: the runtime's fixed-seed 64x64
                     // noise texture (the thesis's)
    };
    size_t parameter = 0;  // CompiledEffect::parameters index
    Kind kind = Kind::File;
    // Texture2D, TextureCube, Texture3D, or a D3D10 Texture1DArray, Texture2DArray, TextureCubeArray,
    // Texture2DMS, Texture2DMSArray
    BaseType type = BaseType::Texture2D;
    TextureFormat format = TextureFormat::RGBA8;
    int arraySize = 1;  // an array's elements (`int ArraySize = N;`, cubes for a TextureCubeArray)
    int samples = 1;    // Texture2DMS<T, N>, Texture2DMSArray<T, N>: N (1 when the type leaves it out)
    int width = 0;      // Dimensions / width,height annotations; 0 when sized by viewportRatio
    int height = 0;
    int depth = 1;  // a texture function's Texture3D: its slices (Dimensions.z or the depth annotation)
    float viewportRatio[2] = {1.0f, 1.0f};  // ViewPortRatio (used when width == 0)
    int mipLevels = 1;
    std::string resourceName;  // ResourceName as written
    std::string resolvedPath;  // relative to the effect file; "" if not found
    uint32_t seed = 0;         // Kind::Procedural: the Seed annotation
    // Kind::Function: a pass of generated stages around the effect's function (docs/fxcomposer.md,
    // "Texture functions"). Its vertex stage draws one triangle over the target and reads its one compile
    // argument, `fx_fill`: xyz the texel size of the level drawn, w the slice's coordinate (a volume) or
    // the face (a cube, 0..5 in GL's order); its pixel stage calls the function once per texel.
    std::optional<CompiledPass> fill;
    SourceLoc loc;
};

struct SamplerDesc {
    size_t parameter = 0;                             // CompiledEffect::parameters index of the sampler
    std::optional<size_t> texture;                    // CompiledEffect::parameters index of its texture
    int addressU = 1, addressV = 1, addressW = 1;     // D3D9 TEXTUREADDRESS values (1 = WRAP)
    int minFilter = 1, magFilter = 1, mipFilter = 0;  // D3D9 TEXF values
    float borderColor[4] = {0, 0, 0, 0};
    int maxAnisotropy = 1;
    float mipLodBias = 0.0f;
    float minLod = -1000.0f, maxLod = 1000.0f;  // D3D10 MinLOD/MaxLOD (GL's defaults otherwise)
    int comparisonFunc = 0;  // D3D9 CMP value; 0 = none (depth targets compare with LESSEQUAL by default)
    SourceLoc loc;
};

// A Buffer<T>'s texels, T resolved from its declaration (`Buffer<uint2>`; a Buffer without <T> reads
// float4s): GL buffer textures hold 32-bit float, int and uint elements of 1 to 4 components.
struct BufferTexel {
    BaseType component = BaseType::Float;  // Float, Int or UInt
    int components = 0;                    // 1 to 4 on a Buffer<T>; 0 on every other parameter
};

// A member of a struct parameter bound by its name, as an application setting a light or a material held
// in a struct would set it (docs/effect-format.md, "What the runtime provides"): Luna's `DirectionalLight
// gDirLights[3]` with its `Diffuse` and `Direction`, a `Material`'s `Diffuse`.
struct MemberBinding {
    std::string member;           // the member's name ("Diffuse")
    TypeDesc type;                // the member's type (numeric, no array)
    uint32_t firstComponent = 0;  // of the member in the parameter's value (in element 0 of an array)
    uint32_t elementStride = 0;   // the numbers of one element of an array parameter (0: no array)
    SemanticBinding standard;     // what the runtime gives it; eachLight: element k is the scene's light k
};

// An effect parameter as the runtime sees it: what it binds by semantic and the annotations it reads,
// resolved at compile time.
struct ParameterInfo {
    std::string name;
    TypeDesc type;
    std::string semantic;      // as written; "" if none
    SemanticBinding standard;  // what the runtime gives it by `semantic` (or by its name, without one)
    bool isStatic = false;
    bool isShared = false;  // declared `shared`: one value across the effects of a pool
    SourceLoc loc;
    // `string frustum = "light0";` or `string Object = "light0";`: the light whose matrices or properties
    // the parameter sees ("" = none: the render port's).
    std::string light;
    // `string Parameterization = "LiSPSM";` on a light matrix: the provider's name as written (the runtime
    // owns the list of providers and reports names it does not know at `parameterizationLoc`).
    bool hasParameterization = false;
    std::string parameterization;  // "" if the annotation is not a string
    SourceLoc parameterizationLoc;
    // What the runtime makes for a buffer or read-write texture at load (docs/d3d10.md, "Compute shaders
    // and read-write resources"), resolved and checked here so that it reads no annotation by name.
    // `string ViewOf = "...";`: the CompiledEffect::parameters index of the buffer or read-write texture
    // whose contents this parameter reads (nullopt: its own).
    std::optional<size_t> viewOf;
    // A StructuredBuffer's, ByteAddressBuffer's (and their read-write, append and consume forms') or an
    // RWBuffer's `int ElementCount = N;`: the elements it holds from load on (1 without it).
    uint32_t elementCount = 1;
    // An RWTexture's `int Width`, `Height` (64 without them; 1 for an RWTexture1D's height) and the `Depth`
    // of an RWTexture3D or `ArraySize` of an RWTexture2DArray (1; 1 for the other kinds).
    int imageSize[3] = {64, 64, 1};
    // An RWTexture's or RWBuffer's texels: the format the code of the first pass using it declares
    // (glslang's, from the element type; ImageBinding::format). nullopt where no pass uses it.
    std::optional<TextureFormat> imageFormat;
    BufferTexel bufferTexel;  // a Buffer<T>'s
    Annotations annotations;  // every annotation of the parameter, in source order (UIName, UIMin, ...)
    // A light or material struct without a semantic: its members bound by their names (`standard` is
    // None then).
    std::vector<MemberBinding> memberBindings;
};

// A struct that parameters have as their type, directly or through members of other structs. Its value
// is its members' numbers in declaration order (CompiledEffect::componentCount), as D3DX's SetRawValue
// takes a struct's floats.
struct StructMemberInfo {
    std::string name;
    TypeDesc type;         // numeric, or a struct listed before this one in CompiledEffect::structs
    std::string semantic;  // as written; "" if none
};
struct StructInfo {
    std::string name;
    std::vector<StructMemberInfo> members;
};

// Where a compiled effect came from, recorded in its file (fx/CompiledEffectFile.h) and printed by
// `shadowfx info`: what to compile again when the file is older than the source.
struct EffectProvenance {
    std::string sourcePath;                                    // the .fx file as the compiler was given it
    std::vector<std::pair<std::string, std::string>> defines;  // -D NAME=VALUE, in order
    std::vector<std::string> includeDirs;                      // -I, in order
    std::string compilerVersion;                               // "shadowfx 0.1.0"
};

struct CompiledEffect {
    std::string path;                       // the effect's main file, for diagnostics
    std::vector<ParameterInfo> parameters;  // one per Effect::parameters entry, same indices
    std::vector<Value> initialValues;       // one per Effect::parameters entry (evaluated initializers)
    std::vector<StructInfo> structs;        // the structs parameters are of, each after those it holds
    std::vector<TextureDesc> textures;
    std::vector<SamplerDesc> samplers;
    // The states samplers have in the passes that set their registers' (SamplerBinding::passSampler): the
    // sampler's own with the pass's applied, `parameter` the sampler's.
    std::vector<SamplerDesc> passSamplers;
    std::vector<CompiledTechnique> techniques;
    std::vector<RefusedTechnique> refusedTechniques;  // left out by the parser or the compiler
    bool hasGlobalScript = false;
    // The STANDARDSGLOBAL parameter's `ScriptClass = "scene"`: FX Composer handed such an effect the frame
    // as it left it in the last frame (the runtime's host clears it only in a frame that starts a picture).
    bool sceneClass = false;
    std::vector<ScriptCommand> globalScript;  // the STANDARDSGLOBAL parameter's Script
    // Every light the effect names, once each, as written: the parameters' `frustum`/`Object`
    // annotations and the light0 of a light property without one, in parameter order, then the scripts'
    // RenderPort=lightN (ScriptCommand::light and SemanticBinding::light index it). The runtime finds each
    // in the scene by name, since only the scene knows its lights.
    std::vector<std::string> lights;
    // The most iterations one LoopByCount may run (CompileOptions::maxScriptLoopCount): the compiler
    // checks literal counts, the runtime a parameter's value.
    int maxScriptLoopCount = 1024;
    EffectProvenance provenance;  // filled by whoever compiles from source with the options it used

    // By name; a technique in an fxgroup also by "group.name".
    const CompiledTechnique* findTechnique(const std::string& name) const;
    const ParameterInfo* findParameter(const std::string& name) const;  // case-sensitive, as HLSL
    const TextureDesc* findTexture(size_t parameter) const;
    const SamplerDesc* findSampler(size_t parameter) const;
    const StructInfo* findStruct(const std::string& name) const;
    // The numbers a value of `type` holds: TypeDesc::componentCount, with a struct's members counted (0 for
    // a struct this effect does not list).
    size_t componentCount(const TypeDesc& type) const;
};

}  // namespace fx
