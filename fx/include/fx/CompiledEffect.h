// CompiledEffect: what the effect compiler hands the runtime. Per technique and pass: GLSL for each stage
// with reflection (which uniform-block member, sampler and vertex input is which effect parameter,
// compile argument or semantic), the pass's render states and its SAS script; per effect: initial
// parameter values, textures and samplers. No OpenGL here: the runtime turns this into GL objects.
#pragma once

#include <fx/Effect.h>
#include <fx/RenderStates.h>
#include <fx/SasScript.h>
#include <fx/Value.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fx {

enum class ShaderStage { Vertex, Fragment };

// One member of a stage's uniform block (std140; offsets and strides from SPIRV-Cross reflection).
struct UniformBinding {
    enum class Source { Parameter, CompileArgument };
    std::string name;  // the member's name in the block
    Source source = Source::Parameter;
    size_t index = 0;     // Effect::parameters index, or CompiledPass::arguments index
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
};

struct SamplerBinding {
    std::string glslName;         // the sampler uniform in the GLSL
    int unit = 0;                 // texture unit (layout(binding) in the GLSL)
    size_t samplerParameter = 0;  // Effect::parameters index of the effect's sampler
    bool depthCompare = false;    // a sampler2DShadow: the bound texture must compare
};

// A vertex shader input, bound by semantic ("POSITION", "NORMAL", "TEXCOORD0", "COLOR0", "TANGENT",
// "BINORMAL"): the runtime feeds the mesh attribute with that semantic, or a defined default.
struct VertexInput {
    std::string semantic;  // upper case, index included: "TEXCOORD0"
    int location = 0;
    int components = 4;
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
    std::vector<SamplerBinding> samplers;
    std::vector<VertexInput> inputs;  // vertex stage
    uint64_t sourceHash = 0;          // hash of hlsl + options: the compile cache's key
};

// An argument of a compile expression bound to a `uniform` entry-point parameter; the runtime evaluates
// `expr` with the preshader before each draw and stores it in the uniform block member that names it.
struct CompileArgument {
    Expr expr;
    TypeDesc type;
    std::string memberName;  // "fx_arg0", ...
};

struct RenderStateSetting {
    RenderStateId id;
    // Folded to a Number/Bool literal when constant; otherwise an expression the runtime evaluates.
    Expr value;
    SourceLoc loc;
};

struct CompiledPass {
    std::string name;
    SourceLoc loc;
    StageProgram vertex;
    StageProgram fragment;
    std::vector<CompileArgument> arguments;
    std::vector<RenderStateSetting> states;  // in source order, shaders excluded
    bool hasScript = false;
    std::vector<ScriptCommand> script;  // the pass's Script annotation (no script: Draw=Geometry)
};

struct CompiledTechnique {
    std::string name;
    SourceLoc loc;
    std::vector<CompiledPass> passes;
    bool hasScript = false;
    std::vector<ScriptCommand> script;  // the technique's Script annotation (no script: every pass in order)
};

enum class TextureFormat {
    RGBA8,
    RGBA16F,
    RGBA32F,
    R16F,
    R32F,
    RG16F,
    RG32F,
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
        Runtime,     // other semantics (e.g. "noise"): the runtime supplies it, or a neutral one
        Procedural,  // `string Procedural = "noise"`: white noise generated at effect creation (the only
                     // generator so far; runtime/render/include/private/runtime/ProceduralTexture.h)
    };
    size_t parameter = 0;  // Effect::parameters index
    Kind kind = Kind::File;
    BaseType type = BaseType::Texture2D;  // Texture2D or TextureCube
    TextureFormat format = TextureFormat::RGBA8;
    int width = 0;  // Dimensions / width,height annotations; 0 when sized by viewportRatio
    int height = 0;
    float viewportRatio[2] = {1.0f, 1.0f};  // ViewPortRatio (used when width == 0)
    int mipLevels = 1;
    std::string resourceName;  // ResourceName as written
    std::string resolvedPath;  // relative to the effect file; "" if not found
    uint32_t seed = 0;         // Kind::Procedural: the Seed annotation
    SourceLoc loc;
};

struct SamplerDesc {
    size_t parameter = 0;                             // Effect::parameters index of the sampler
    std::optional<size_t> texture;                    // Effect::parameters index of its texture
    int addressU = 1, addressV = 1, addressW = 1;     // D3D9 TEXTUREADDRESS values (1 = WRAP)
    int minFilter = 1, magFilter = 1, mipFilter = 0;  // D3D9 TEXF values
    float borderColor[4] = {0, 0, 0, 0};
    int maxAnisotropy = 1;
    float mipLodBias = 0.0f;
    int comparisonFunc = 0;  // D3D9 CMP value; 0 = none (depth targets compare with LESSEQUAL by default)
    SourceLoc loc;
};

struct CompiledEffect {
    std::shared_ptr<const Effect> effect;
    std::vector<Value> initialValues;  // one per Effect::parameters entry (evaluated initializers)
    std::vector<TextureDesc> textures;
    std::vector<SamplerDesc> samplers;
    std::vector<CompiledTechnique> techniques;
    bool hasGlobalScript = false;
    std::vector<ScriptCommand> globalScript;  // the STANDARDSGLOBAL parameter's Script

    const CompiledTechnique* findTechnique(const std::string& name) const;
    const TextureDesc* findTexture(size_t parameter) const;
    const SamplerDesc* findSampler(size_t parameter) const;
};

}  // namespace fx
