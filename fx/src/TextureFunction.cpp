// TextureFunction: FX Composer's texture functions (`texture t < string function = "f"; >`), which D3DX's
// D3DXFillTextureTX ran once per texel of every level when the effect was created: `f` takes the texel's
// centre (POSITION: 0..1 in each dimension of a 2D or volume texture, a direction -1..1 for a cube) and
// the texel's size (PSIZE) and returns its colour. shadowfx draws it: the texture's `fill` pass is a
// generated vertex stage covering the target with one triangle and a generated pixel stage that calls the
// effect's function, compiled with every other stage of the effect (see Compiler.h).

#include "Compiler.h"
#include "HlslRewriting.h"
#include "SemanticTables.h"

#include "CaseFolding.h"

namespace fx::detail {

namespace {

// What the runtime gives the fill pass's vertex stage per draw (CompiledEffect.h, TextureDesc::fill).
constexpr const char* kFillArgument = "fx_fill";

constexpr const char* kFillVertexShader = R"(// shadowfx: texture function fill, vertex stage
float4 fx_fill;
struct fx_FillVertex {
    float4 position : SV_Position;
    [[vk::location(0)]] float3 coord : TEXCOORD0;
    [[vk::location(1)]] float3 texel : TEXCOORD1;
};
fx_FillVertex fx_main(uint id : SV_VertexID)
{
    // One triangle over the target: corners (0,0), (2,0), (0,2) in texel coordinates, so that each pixel
    // centre reads its texel's centre. Texel row 0 is at the top, as the runtime's clip control has it.
    const float2 corner = float2((id << 1) & 2, id & 2);
    fx_FillVertex v;
    v.position = float4(corner.x * 2.0 - 1.0, 1.0 - corner.y * 2.0, 0.0, 1.0);
    v.coord = float3(corner, fx_fill.w);
    v.texel = fx_fill.xyz;
    return v;
}
)";

// A cube face's texel (s, t in -1..1, t down) as the direction D3D and GL sample it by, per face in
// GL's order (+X, -X, +Y, -Y, +Z, -Z): the major axis, then the face's s and t axes.
constexpr const char* kCubeDirection =
    "    const float fx_s = fx_coord.x * 2.0 - 1.0, fx_t = fx_coord.y * 2.0 - 1.0;\n"
    "    const int fx_face = (int)fx_coord.z;\n"
    "    const float3 fx_position = fx_face == 0 ? float3(1.0, -fx_t, -fx_s)\n"
    "                             : fx_face == 1 ? float3(-1.0, -fx_t, fx_s)\n"
    "                             : fx_face == 2 ? float3(fx_s, 1.0, fx_t)\n"
    "                             : fx_face == 3 ? float3(fx_s, -1.0, -fx_t)\n"
    "                             : fx_face == 4 ? float3(fx_s, -fx_t, 1.0)\n"
    "                                            : float3(-fx_s, -fx_t, -1.0);\n";

std::string swizzle(int components) {
    return components == 1 ? ".x" : components == 2 ? ".xy" : ".xyz";
}

int componentCount(const TypeDesc& type) {
    return type.shape == Shape::Scalar ? 1 : type.shape == Shape::Vector ? type.cols : 0;
}

}  // namespace

// `string function = "f";` on a texture: checked here, lowered once every texture is known.
void Compiler::textureFunction(const Parameter& p, const Annotation& annotation, TextureDesc& t) {
    const bool fillable =
        t.type == BaseType::Texture2D || t.type == BaseType::Texture3D || t.type == BaseType::TextureCube;
    if (t.kind != TextureDesc::Kind::Runtime || !fillable || isDepthFormat(t.format)) {
        error(DiagId::TextureFunctionTarget, annotation.loc, {p.name});
        return;
    }
    const std::string name = annotation.value.kind == Expr::Kind::String ? annotation.value.text : "";
    const FunctionDecl* function = nullptr;
    for (const FunctionDecl* f : mEffect.findFunctions(name))
        if (f->hasBody) function = f;
    if (!function) {
        error(DiagId::TextureFunctionUndefined, annotation.value.loc, {annotation.value.str()});
        return;
    }
    t.kind = TextureDesc::Kind::Function;
    // D3DXFillTexture fills every level the texture has: a full chain unless MipLevels says otherwise.
    if (!p.annotation("MipLevels")) t.mipLevels = 0;
    if (t.width == 0) t.width = t.height = 64;
    if (t.type == BaseType::TextureCube) t.height = t.width;
    if (t.type == BaseType::Texture3D) {
        TypeDesc scalar;
        if (const Annotation* d = p.annotation("depth")) {
            if (auto v = eval(d->value, &scalar)) t.depth = static_cast<int>(v->asFloat());
        } else if (const Annotation* dims = p.annotation("Dimensions")) {
            std::optional<Value> v = eval(dims->value, nullptr);
            t.depth = v && v->data.size() >= 3 ? static_cast<int>(v->data[2]) : t.width;
        } else {
            t.depth = t.width;
        }
        if (!(t.depth >= 1 && t.depth <= 2048)) {
            error(DiagId::VolumeDepthOutOfRange, p.loc, {});
            return;
        }
    }
    mTextureFunctions.push_back(TextureFunctionRequest{mOut->textures.size(), function, annotation.loc});
}

void Compiler::lowerTextureFunctions() {
    for (const TextureFunctionRequest& request : mTextureFunctions) {
        const FunctionDecl& fn = *request.function;
        TextureDesc& texture = mOut->textures[request.texture];

        // The function's parameters, each given by its semantic.
        std::string arguments;
        bool ok = true;
        for (const FunctionParam& param : fn.params) {
            const std::string semantic = splitSemantic(canonicalSemantic(param.semantic)).first;
            const int components = componentCount(param.type);
            const bool floating = param.type.base == BaseType::Float || param.type.base == BaseType::Half;
            if ((semantic != "POSITION" && semantic != "PSIZE") || !floating || components < 1 ||
                components > 3 || param.direction != FunctionParam::Direction::In) {
                error(DiagId::TextureFunctionParameter, fn.loc,
                      {fn.name, param.name,
                       param.type.hlslName() + (param.semantic.empty() ? "" : " : ") + param.semantic});
                ok = false;
                continue;
            }
            if (!arguments.empty()) arguments += ", ";
            // Both are float3, 0 beyond the texture's dimensions.
            arguments += (semantic == "POSITION" ? "fx_position" : "fx_texel") + swizzle(components);
        }
        const int returned = componentCount(fn.returnType);
        if (returned < 1 || returned > 4 ||
            (fn.returnType.base != BaseType::Float && fn.returnType.base != BaseType::Half)) {
            error(DiagId::TextureFunctionReturn, fn.loc, {fn.name, fn.returnType.hlslName()});
            ok = false;
        }
        if (!ok) continue;

        // D3D's rule for the channels a colour leaves out: 0, and 1 for alpha.
        const std::string call = fn.name + "(" + arguments + ")";
        const std::string colour = returned == 4   ? call
                                   : returned == 3 ? "float4(" + call + ", 1.0)"
                                   : returned == 2 ? "float4(" + call + ", 0.0, 1.0)"
                                                   : "float4(" + call + ", 0.0, 0.0, 1.0)";
        std::string wrapper =
            "float4 fx_main([[vk::location(0)]] float3 fx_coord : TEXCOORD0,\n"
            "               [[vk::location(1)]] float3 fx_texel : TEXCOORD1) : SV_Target0\n{\n";
        const std::string position = texture.type == BaseType::TextureCube
                                         ? std::string(kCubeDirection)
                                         : "    const float3 fx_position = fx_coord;\n";
        const std::string body = position + "    return " + colour + ";\n}\n";

        // The runtime fills the texture when it creates the effect, before any other texture is ready, and
        // binds none: the function may read values, not resources.
        const std::set<std::string> reached = reachableFunctions(mEffect, fn.name);
        for (const FunctionDecl& f : mEffect.functions) {
            if (!reached.count(f.name)) continue;
            for (const std::string& id : identifiersIn(f.hlslText)) {
                const Parameter* read = mEffect.findParameter(id);
                if (read && (isSamplerType(read->type) || read->type.isTexture() || read->type.isBuffer())) {
                    error(DiagId::TextureFunctionSamples, request.loc, {fn.name, id});
                    ok = false;
                    break;
                }
            }
        }
        if (!ok) continue;
        const EffectDeclarations declarations = emitEffectDeclarations(mEffect, reached, wrapper + body);
        LoweredStage fragment;
        fragment.stage = ShaderStage::Fragment;
        fragment.entryPoint = fn.name;
        fragment.profile = "tx_1_0";  // D3DX's texture-shader profile
        fragment.compileLoc = request.loc;
        fragment.hlsl = "// shadowfx: texture function " + fn.name + "\n" + declarations.hlsl + "#line 1 \"" +
                        kGeneratedFile + "\"\n" + wrapper + declarations.staticAssignments + "#line 1 \"" +
                        kGeneratedFile + "\"\n" + body;
        fragment.depthSamplers = declarations.depthSamplers;

        LoweredStage vertex;
        vertex.stage = ShaderStage::Vertex;
        vertex.entryPoint = "fx_main";
        vertex.profile = "tx_1_0";
        vertex.compileLoc = request.loc;
        vertex.hlsl = kFillVertexShader;

        CompiledPass& fill = texture.fill.emplace();
        fill.name = "fill " + fn.name;
        fill.loc = request.loc;
        TypeDesc float4;
        float4.shape = Shape::Vector;
        float4.cols = 4;
        fill.arguments.push_back(CompileArgument{PreshaderProgram{}, float4, kFillArgument});
        const PassSlot slot{PassSlot::kTextureFill, request.texture};
        enqueueStage(std::move(vertex), fill, slot);
        enqueueStage(std::move(fragment), fill, slot);
    }
}

}  // namespace fx::detail
