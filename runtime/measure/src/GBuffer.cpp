// GBuffer: a one-pass built-in effect with two float render targets (position + object id, normal),
// rendered by EffectRenderer and read back. Going through the effect runtime rather than a private GL
// program keeps the camera matrices, clip conventions and culling identical to every effect's frame.
#include <runtime/GBuffer.h>

#include <fx/EffectCompiler.h>
#include <fx/EffectParser.h>
#include <runtime/EffectRenderer.h>

#include <cmath>

namespace runtime {

namespace {

// D3D's default CullMode (CCW) as in the effects' scene passes: a pixel the effect shows is a pixel here.
// Object ids travel in position.w (float32 is exact for ids below 2^24); the clear leaves 0 = background.
constexpr const char* kGBufferEffect = R"(
float4x4 WorldViewProjection : WorldViewProjection;
float4x4 World : World;
float4x4 WorldIT : WorldInverseTranspose;
float ObjectIndex : ObjectId;
float4 ClearZero = {0, 0, 0, 0};
float ClearDepth = 1.0;

texture GPosition : RENDERCOLORTARGET < float2 ViewPortRatio = {1, 1}; string Format = "A32B32G32R32F"; >;
texture GNormal : RENDERCOLORTARGET < float2 ViewPortRatio = {1, 1}; string Format = "A32B32G32R32F"; >;

struct GBufferVertex { float4 HPosition : POSITION; float3 WorldPosition : TEXCOORD0; float3 WorldNormal : TEXCOORD1; };
struct GBufferPixel { float4 Position : COLOR0; float4 Normal : COLOR1; };

GBufferVertex GBufferVS(float4 Position : POSITION, float3 Normal : NORMAL)
{
    GBufferVertex OUT;
    float4 p = float4(Position.xyz, 1.0);
    OUT.HPosition = mul(p, WorldViewProjection);
    OUT.WorldPosition = mul(p, World).xyz;
    OUT.WorldNormal = mul(Normal, (float3x3)WorldIT);
    return OUT;
}

GBufferPixel GBufferPS(GBufferVertex IN)
{
    GBufferPixel OUT;
    OUT.Position = float4(IN.WorldPosition, ObjectIndex);
    OUT.Normal = float4(normalize(IN.WorldNormal), 1.0);
    return OUT;
}

technique gbuffer < string Script = "Pass=Fill;"; >
{
    pass Fill
    <
        string Script = "RenderColorTarget0=GPosition;"
                        "RenderColorTarget1=GNormal;"
                        "RenderDepthStencilTarget=;"
                        "RenderPort=;"
                        "ClearSetColor=ClearZero;"
                        "ClearSetDepth=ClearDepth;"
                        "Clear=Color;"
                        "Clear=Depth;"
                        "Draw=Geometry;";
    >
    {
        CullMode = CCW;
        ZEnable = true;
        ZWriteEnable = true;
        ZFunc = LessEqual;
        AlphaBlendEnable = false;
        VertexShader = compile vs_3_0 GBufferVS();
        PixelShader = compile ps_3_0 GBufferPS();
    }
}
)";

}  // namespace

std::optional<GBuffer> renderGBuffer(const Scene& scene, int width, int height,
                                     fx::DiagnosticSink& diagnostics) {
    std::shared_ptr<fx::Effect> effect =
        fx::parseEffectSource(kGBufferEffect, "<shadowfx gbuffer>", fx::ParseOptions{}, diagnostics);
    if (!effect) return std::nullopt;
    std::shared_ptr<fx::CompiledEffect> compiled =
        fx::compileEffect(effect, fx::CompileOptions{}, diagnostics);
    if (!compiled) return std::nullopt;
    std::unique_ptr<EffectRenderer> renderer = EffectRenderer::create(compiled, diagnostics);
    if (!renderer) return std::nullopt;

    // Scenes number their objects as they like (or not at all); here the id must name the object's index.
    Scene numbered = scene;
    for (size_t i = 0; i < numbered.objects.size(); ++i)
        numbered.objects[i].id = static_cast<uint32_t>(i + 1);

    FrameOptions options;
    options.width = width;
    options.height = height;
    options.outputTargets = {"GPosition", "GNormal"};
    if (!renderer->render(numbered, options, diagnostics)) return std::nullopt;

    int w = 0, h = 0, positionChannels = 0, normalChannels = 0;
    std::optional<std::vector<float>> positions =
        renderer->readTarget("GPosition", &w, &h, &positionChannels);
    std::optional<std::vector<float>> normals = renderer->readTarget("GNormal", &w, &h, &normalChannels);
    if (!positions || !normals || w != width || h != height || positionChannels < 4 || normalChannels < 3)
        return std::nullopt;

    // The runtime rendered the scene relative to its render origin (Scene.h); positions are world space.
    const glm::vec3 origin = renderOrigin(numbered);
    GBuffer gbuffer;
    gbuffer.width = width;
    gbuffer.height = height;
    gbuffer.position.resize(gbuffer.pixelCount());
    gbuffer.normal.resize(gbuffer.pixelCount());
    gbuffer.objectId.resize(gbuffer.pixelCount());
    for (size_t i = 0; i < gbuffer.pixelCount(); ++i) {
        const float* p = &(*positions)[i * static_cast<size_t>(positionChannels)];
        const float* n = &(*normals)[i * static_cast<size_t>(normalChannels)];
        gbuffer.position[i] = glm::vec3(p[0], p[1], p[2]) + origin;
        gbuffer.normal[i] = glm::vec3(n[0], n[1], n[2]);
        gbuffer.objectId[i] = static_cast<uint32_t>(std::lround(std::max(0.0f, p[3])));
    }
    return gbuffer;
}

}  // namespace runtime
