// izb.fx: exact hard shadows by an irregular z-buffer (Johnson, Mark & Burns 2005; Aila & Laine 2004, the
// same method as alias-free shadow maps): the shadow test runs at the camera's own samples instead of the
// light's, so a silhouette is exact wherever it falls between a shadow map's texels
// (docs/techniques/exact-shadows.md).
//
// 1. `ClearHeads`: every light-map texel's list of receivers is emptied.
// 2. `Receivers`: the camera's view; each pixel stores its receiver's light position (NDC x, y and depth z),
//    the visible point moved ReceiverOffset off its plane along the ray to the light, as the ray-cast
//    truth starts its rays (docs/scoring.md, "The ground truth").
// 3. `Build`: each pixel's receiver (node index = pixel index) is copied into its node and pushed onto the
//    list of the texel it projects to (an atomic exchange on that texel's head).
// 4. `Occlude`: the casters from the light, conservatively rasterized (each triangle enlarged by half a
//    texel and clipped to its box, Hasselgren, Akenine-Möller & Ohlsson 2005; a closed mesh's triangles
//    that face away from the light left out, as they shadow nothing the others do not): every texel a
//    triangle touches walks its list and tests each receiver against the triangle itself, point in
//    triangle in the light's x, y and the triangle's depth there in front of the receiver; a hit marks the
//    node shadowed.
// 5. `Shade`: the scene, each pixel shaded from its node's mark.
//
// The light matrices are LiSPSM's fit (lispsm.fx): the map's texels only decide which triangles meet which
// receivers, never the answer; a fit to what the camera sees keeps the lists short.
#define LIGHT_PARAMETERIZATION "LiSPSM"
#include "include/lighting.fxh"
#include "include/shadowscene.fxh"

#ifdef SHADOWFX_SHADOW_MAP_SIZE
#define SHADOW_MAP_SIZE SHADOWFX_SHADOW_MAP_SIZE
#else
#define SHADOW_MAP_SIZE 1024
#endif

// The receivers the buffers hold: one node per frame pixel, up to 2560x1600 or 2048x2048 (4,194,304). A
// larger frame's pixels past the last node are drawn in MissingNodeColor, never shadowed or lit by guess.
#define RECEIVER_CAPACITY 4194304
// A node's link holds the next node + 1 (0 ends the list) in its low bits and the shadowed mark in bit 30:
// the capacity stays below 2^30.
#define NODE_SHADOWED 0x40000000

float Script : STANDARDSGLOBAL
<
    string UIWidget = "none";
    string ScriptClass = "scene";
    string ScriptOrder = "standard";
    string ScriptOutput = "color";
    string Script = "Technique=exact;";
> = 0.8;

// [SECTION] Tweakables
// How far the receiver moves off its plane (on the light's side, along its ray to the light) before the
// test, as a fraction of the light frustum's width at the receiver: the receiver's own triangle lies
// behind it, where float rounding would otherwise let it shadow itself. A fraction, not world units, so
// that a scene scaled by 1e-3 or 1e4 is answered alike (stress cases scaled-1e-3, scaled-1e4); the ray-cast
// truth starts 1e-4 of the scene's radius off the plane, about half this default where the fit spans the
// scene.
float ReceiverOffset
<
    string UIWidget = "slider";
    string UIName = "Receiver offset off its plane (fraction of the light frustum's width)";
    float UIMin = 0.000001;
    float UIMax = 0.001;
    string UIScale = "log";
> = 0.0001;

// The fit's tunables, as lispsm.fx declares them: they move texels, never the answer, only the time.
bool FitVisible : LightFitVisibleSamples
<
    string UIName = "Fit to the visible samples";
> = false;

float NScale : LiSPSMNScale
<
    string UIWidget = "slider";
    string UIName = "LiSPSM n / n_opt";
    float UIMin = 0.25;
    float UIMax = 8.0;
> = 1.0;

float4 NoReceiver <string UIWidget = "none";> = {0.0, 0.0, 0.0, 0.0};
float4 MissingNodeColor <string UIWidget = "color";> = {1.0, 0.0, 1.0, 1.0};

// [SECTION] Buffers and targets
// Each light-map texel's first node + 1 (0: an empty list); ClearHeads empties them every frame.
RWStructuredBuffer<uint> Heads < int ElementCount = SHADOW_MAP_SIZE * SHADOW_MAP_SIZE; >;
// One node per frame pixel: its receiver's light position, and its link with the shadowed mark
// (NODE_SHADOWED). Build writes every pixel's every frame; a list walk reads a node's 16 bytes at once.
struct ReceiverNode
{
    float3 Light;
    int Link;
};
RWStructuredBuffer<ReceiverNode> Nodes < int ElementCount = RECEIVER_CAPACITY; >;

// The receivers' light positions (xyz) and whether the pixel holds a receiver the lists test (w = 1).
Texture2D<float4> Receivers : RENDERCOLORTARGET
<
    float2 ViewPortRatio = {1.0, 1.0};
    string Format = "A32B32G32R32F";
    string UIWidget = "None";
>;

// The light passes' viewport (no colour is written: their draws run as depth-only passes).
texture LightTarget : RENDERCOLORTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "R16F";
    string UIWidget = "None";
>;
texture LightDepth : RENDERDEPTHSTENCILTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "D16";
    string UIWidget = "None";
>;

// [SECTION] Shaders
struct QuadVertex
{
    float4 Position : POSITION;
    float2 UV       : TEXCOORD0;
};

float4 QuadVS(QuadVertex IN) : SV_Position
{
    return IN.Position;
}

// Light NDC -> texel coordinates of the map (x right, y down, texel centres at i + 0.5), as ShadowMapUV
// (shadowmap.fxh) addresses a map.
float2 TexelOf(float2 ndc)
{
    return (float2(0.5, -0.5) * ndc + 0.5) * SHADOW_MAP_SIZE;
}

float4 ClearHeadsPS(float4 position : SV_Position) : SV_Target
{
    uint2 texel = uint2(position.xy);
    Heads[texel.y * SHADOW_MAP_SIZE + texel.x] = 0;
    return 0;
}

struct ReceiverPixel
{
    float4 Position : SV_Position;
    float3 World    : TEXCOORD0;
    float3 WNormal  : TEXCOORD1;
};

ReceiverPixel ReceiverVS(VertexFormat IN)
{
    ReceiverPixel OUT;
    float4 position = float4(IN.Position.xyz, 1.0);
    OUT.World = mul(position, WorldMatrix).xyz;
    OUT.WNormal = mul(IN.Normal, (float3x3)WorldITMatrix);
    OUT.Position = mul(position, WorldViewProjectionMatrix);
    return OUT;
}

// The receiver moved `height` off its plane, reached along its ray to the light, as the ray-cast truth starts
// its rays (docs/scoring.md, "The ground truth"): along the ray its light x, y stay, so its shadow's edges
// stay where the casters put them (a move along the normal shifts them by height / tan(elevation)); where
// the light grazes the surface (N.L < 0.1) the normal makes up what the ray's ten heights lack.
float3 OffPlaneTowardsLight(float3 world, float3 normal, float3 toLight, float height)
{
    float cosine = dot(normal, toLight);
    float along = height / max(cosine, 0.1);
    return world + toLight * along + normal * (height - along * cosine);
}

// A receiver the metrics count faces the light (N.L > 0, docs/scoring.md); one facing away is dark
// whatever its shadow, and is left out of the lists.
float4 ReceiverPS(ReceiverPixel IN) : SV_Target
{
    float3 normal = normalize(IN.WNormal);
    float3 toLight = normalize(DirectionToLight());
    if (dot(normal, toLight) <= 0.0)
        return NoReceiver;
    float4 visible = mul(float4(IN.World, 1.0), LightViewProjectionMatrix);
    if (visible.w <= 0.0)
        return NoReceiver;
    float frustumWidth = 2.0 * visible.w / abs(LightProjectionMatrix._11);
    float4 clip = mul(float4(OffPlaneTowardsLight(IN.World, normal, toLight, ReceiverOffset * frustumWidth), 1.0),
                      LightViewProjectionMatrix);
    if (clip.w <= 0.0)
        return NoReceiver;
    float3 ndc = clip.xyz / clip.w;
    if (any(abs(ndc.xy) >= 1.0))
        return NoReceiver;  // outside the map: no texel lists it, so it stays lit, as a clamped map's is
    return float4(ndc, 1.0);
}

float4 BuildPS(float4 position : SV_Position) : SV_Target
{
    uint2 pixel = uint2(position.xy);
    uint width, height;
    Receivers.GetDimensions(width, height);
    uint node = pixel.y * width + pixel.x;
    if (pixel.x >= width || pixel.y >= height || node >= RECEIVER_CAPACITY)
        return 0;
    float4 receiver = Receivers.Load(int3(pixel, 0));
    uint next = 0;
    if (receiver.w > 0.0)
    {
        uint2 texel = min(uint2(TexelOf(receiver.xy)), SHADOW_MAP_SIZE - 1);
        InterlockedExchange(Heads[texel.y * SHADOW_MAP_SIZE + texel.x], node + 1, next);
    }
    ReceiverNode written;
    written.Light = receiver.xyz;
    written.Link = int(next);
    Nodes[node] = written;
    return 0;
}

struct CasterVertex
{
    float4 Position : SV_Position;
};

CasterVertex CasterVS(VertexFormat IN)
{
    CasterVertex OUT;
    OUT.Position = mul(mul(float4(IN.Position.xyz, 1.0), WorldMatrix), LightViewProjectionMatrix);
    return OUT;
}

// The triangle's light NDC vertices (xy, depth z), the same at every pixel it covers, and its box in
// texels grown by half a texel.
struct CasterPixel
{
    float4 Position : SV_Position;
    nointerpolation float3 A : TEXCOORD0;
    nointerpolation float3 B : TEXCOORD1;
    nointerpolation float3 C : TEXCOORD2;
    nointerpolation float4 Box : TEXCOORD3;
};

float Cross2(float2 u, float2 v)
{
    return u.x * v.y - u.y * v.x;
}

// Half a texel and a little more: every texel whose square the triangle touches has its centre inside the
// enlarged triangle and box, float rounding of the edges included.
#define CONSERVATIVE_REACH 0.501

// The line through p and q (texel coordinates, the triangle's inside to its left) moved outward until it
// passes the corner of a texel whose centre is on it, as a homogeneous line (a, b, c): a x + b y + c = 0.
float3 OutsetEdge(float2 p, float2 q)
{
    float2 inward = float2(p.y - q.y, q.x - p.x);
    return float3(inward, -dot(inward, p) + CONSERVATIVE_REACH * (abs(inward.x) + abs(inward.y)));
}

float4 Corner(float3 line1, float3 line2)
{
    float3 meet = cross(line1, line2);
    float2 texel = meet.xy / meet.z;
    return float4(texel / SHADOW_MAP_SIZE * float2(2.0, -2.0) + float2(-1.0, 1.0), 0.5, 1.0);
}

// A triangle behind the light's projection centre (a vertex at w <= 0) or seen edge-on from the light
// (no area in the map) is left out: the first shadows nothing the fit holds, the second nothing but
// receivers exactly on its line.
[maxvertexcount(3)]
void ConservativeGS(triangle CasterVertex IN[3], inout TriangleStream<CasterPixel> stream)
{
    if (min(IN[0].Position.w, min(IN[1].Position.w, IN[2].Position.w)) <= 0.0)
        return;
    CasterPixel OUT;
    OUT.A = IN[0].Position.xyz / IN[0].Position.w;
    OUT.B = IN[1].Position.xyz / IN[1].Position.w;
    OUT.C = IN[2].Position.xyz / IN[2].Position.w;
    float2 p0 = TexelOf(OUT.A.xy);
    float2 p1 = TexelOf(OUT.B.xy);
    float2 p2 = TexelOf(OUT.C.xy);
    float area = Cross2(p1 - p0, p2 - p0);
    if (abs(area) < 1e-6)
        return;
    if (area < 0.0)
    {
        float2 swap = p1;
        p1 = p2;
        p2 = swap;
    }
    OUT.Box = float4(min(p0, min(p1, p2)) - CONSERVATIVE_REACH, max(p0, max(p1, p2)) + CONSERVATIVE_REACH);
    float3 e01 = OutsetEdge(p0, p1);
    float3 e12 = OutsetEdge(p1, p2);
    float3 e20 = OutsetEdge(p2, p0);
    // The corners at the (swapped) p0, p1, p2, emitted in the input triangle's own order: the
    // rasterizer's culling then sees the caster's winding as the light sees it (CullLightBack).
    float4 corners[3] = {Corner(e20, e01), Corner(e01, e12), Corner(e12, e20)};
    uint second = area < 0.0 ? 2 : 1;
    OUT.Position = corners[0];
    stream.Append(OUT);
    OUT.Position = corners[second];
    stream.Append(OUT);
    OUT.Position = corners[3 - second];
    stream.Append(OUT);
}

// Whether the triangle (a, b, c: light NDC) covers the receiver's light x, y with a depth in front of it.
bool Occludes(float3 a, float3 b, float3 c, float3 receiver)
{
    float area = Cross2(b.xy - a.xy, c.xy - a.xy);
    float3 edges = float3(Cross2(c.xy - b.xy, receiver.xy - b.xy), Cross2(a.xy - c.xy, receiver.xy - c.xy),
                          Cross2(b.xy - a.xy, receiver.xy - a.xy)) * sign(area);
    if (any(edges < 0.0))
        return false;
    float3 weights = edges / abs(area);
    return dot(weights, float3(a.z, b.z, c.z)) < receiver.z;
}

float4 OccludePS(CasterPixel IN) : SV_Target
{
    if (any(IN.Position.xy < IN.Box.xy) || any(IN.Position.xy > IN.Box.zw))
        return 0;
    uint2 texel = uint2(IN.Position.xy);
    int link = int(Heads[texel.y * SHADOW_MAP_SIZE + texel.x]);
    for (uint walked = 0; link != 0 && walked < RECEIVER_CAPACITY; ++walked)
    {
        uint node = uint(link - 1);
        ReceiverNode visited = Nodes[node];
        link = visited.Link & ~NODE_SHADOWED;
        if ((visited.Link & NODE_SHADOWED) == 0 && Occludes(IN.A, IN.B, IN.C, visited.Light))
            InterlockedOr(Nodes[node].Link, NODE_SHADOWED);
    }
    return 0;
}

struct ShadePixel
{
    float4 Position : SV_Position;
    float3 LightVec : TEXCOORD0;
    float3 WNormal  : TEXCOORD1;
    float3 WView    : TEXCOORD2;
};

ShadePixel ShadeVS(VertexFormat IN)
{
    SceneVertexOutput scene = RenderSceneVS(IN, LightViewProjectionMatrix);
    ShadePixel OUT;
    OUT.Position = scene.HPosition;
    OUT.LightVec = scene.LightVec;
    OUT.WNormal = scene.WNormal;
    OUT.WView = scene.WView;
    return OUT;
}

float4 ShadePS(ShadePixel IN) : SV_Target
{
    uint2 pixel = uint2(IN.Position.xy);
    uint width, height;
    Receivers.GetDimensions(width, height);
    uint node = pixel.y * width + pixel.x;
    if (pixel.x >= width || pixel.y >= height || node >= RECEIVER_CAPACITY)
        return MissingNodeColor;
    float shadow = (Nodes[node].Link & NODE_SHADOWED) != 0 ? 0.0 : 1.0;
    return ShadedOrVisibility(IN.WNormal, IN.WView, IN.LightVec, shadow);
}

// [SECTION] States
RasterizerState CullBack { CullMode = Back; };
RasterizerState NoCull { CullMode = None; };
// A closed mesh's triangles that face away from the light shadow nothing its light-facing ones do not:
// a ray from a receiver to the light that enters the mesh leaves it through a light-facing triangle.
// Open meshes (a ground plane, a one-sided wall) are drawn whole (CullClosedOnly).
RasterizerState CullLightBack { CullMode = Back; };
DepthStencilState DepthTest { DepthEnable = true; DepthWriteMask = ALL; DepthFunc = LESS_EQUAL; };
DepthStencilState NoDepth { DepthEnable = false; DepthWriteMask = ZERO; };
BlendState NoColour { RenderTargetWriteMask[0] = 0; };
BlendState AllColour { RenderTargetWriteMask[0] = 15; };

// [SECTION] Technique
technique11 exact
<
    string Script = "Pass=ClearHeads; Pass=Receivers; Pass=Build; Pass=Occlude; Pass=Shade;";
    string ExpectScenes = "dual-l,teapot";
    float ExpectMisclassifiedBelow = 0.01;  // measured 0.000 % on dual-l, 0.002 % on the teapot (hard truth)
    int ExpectMapSize = 512;
>
{
    pass ClearHeads
    <
        string Script = "RenderColorTarget0=LightTarget;"
                        "RenderDepthStencilTarget=LightDepth;"
                        "RenderPort=;"
                        "Draw=Buffer;";
    >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetPixelShader(CompileShader(ps_5_0, ClearHeadsPS()));
        SetRasterizerState(NoCull);
        SetDepthStencilState(NoDepth, 0);
        SetBlendState(NoColour, float4(0, 0, 0, 0), 0xFFFFFFFF);
    }
    pass Receivers
    <
        string Script = "RenderColorTarget0=Receivers;"
                        "RenderDepthStencilTarget=;"
                        "RenderPort=;"
                        "ClearSetColor=NoReceiver;"
                        "ClearSetDepth=ClearDepth;"
                        "Clear=Color;"
                        "Clear=Depth;"
                        "Draw=Geometry;";
    >
    {
        SetVertexShader(CompileShader(vs_5_0, ReceiverVS()));
        SetPixelShader(CompileShader(ps_5_0, ReceiverPS()));
        SetRasterizerState(CullBack);
        SetDepthStencilState(DepthTest, 0);
        SetBlendState(AllColour, float4(0, 0, 0, 0), 0xFFFFFFFF);
    }
    pass Build
    <
        string Script = "RenderColorTarget0=;"
                        "RenderDepthStencilTarget=;"
                        "Draw=Buffer;";
    >
    {
        SetVertexShader(CompileShader(vs_5_0, QuadVS()));
        SetPixelShader(CompileShader(ps_5_0, BuildPS()));
        SetRasterizerState(NoCull);
        SetDepthStencilState(NoDepth, 0);
        SetBlendState(NoColour, float4(0, 0, 0, 0), 0xFFFFFFFF);
    }
    pass Occlude
    <
        bool CullClosedOnly = true;
        float FilterReachTexels = 1;
        string Script = "RenderColorTarget0=LightTarget;"
                        "RenderDepthStencilTarget=LightDepth;"
                        "RenderPort=light0;"
                        "Draw=Geometry;";
    >
    {
        SetVertexShader(CompileShader(vs_5_0, CasterVS()));
        SetGeometryShader(CompileShader(gs_5_0, ConservativeGS()));
        SetPixelShader(CompileShader(ps_5_0, OccludePS()));
        SetRasterizerState(CullLightBack);
        SetDepthStencilState(NoDepth, 0);
        SetBlendState(NoColour, float4(0, 0, 0, 0), 0xFFFFFFFF);
    }
    pass Shade
    <
        string Script = "RenderColorTarget0=;"
                        "RenderDepthStencilTarget=;"
                        "RenderPort=;"
                        "ClearSetColor=ClearColor;"
                        "ClearSetDepth=ClearDepth;"
                        "Clear=Color;"
                        "Clear=Depth;"
                        "Draw=Geometry;";
    >
    {
        SetVertexShader(CompileShader(vs_5_0, ShadeVS()));
        SetPixelShader(CompileShader(ps_5_0, ShadePS()));
        SetRasterizerState(CullBack);
        SetDepthStencilState(DepthTest, 0);
        SetBlendState(AllColour, float4(0, 0, 0, 0), 0xFFFFFFFF);
    }
}
