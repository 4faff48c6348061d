// fractional_disk.fx: soft shadows by the lit fraction of a disk (Valient & de Boer 2004):
// the light reaching a receiver point P from a disk light of
// radius r is taken as the lit fraction of a disk of radius q = (d2 / d1) r around P, lit by a point light
// at the disk light's centre (d1: occluder to light, d2: receiver to occluder; "Soft shadows" and Fig. 1b).
// The disk is sampled stochastically with ⌈π q² / a⌉ samples (eq. 2), clamped to MaxSamples.
//
//   preprocessed  the whole algorithm. (1) A back-face map holding linear light distance (eq. 4; here the
//                 light-view depth mapped linearly from the near plane to the far plane) in R: back faces
//                 keep a disk that penetrates its own receiver from shadowing it ("second-depth"). Open
//                 objects (the ground) are drawn whole, so their faces turned towards the light are in the
//                 map too, marked in A (1: front face); a sample of such a texel is tested at the
//                 receiver's tangent plane at the texel's centre (the adaptive depth bias of Dou et al. 2014,
//                 as pcf.fx), since a grazing sun's ground slopes away within one texel by more than any
//                 slope bias covers; a back face's at the receiver's depth less the biases, as the paper. (2) Edge
//                 detection on the map: a texel at a depth discontinuity is on a hard shadow boundary; it
//                 gets the minimum depth of its 3x3 neighbourhood (the occluder) in G and distance 0 in B.
//                 (3) Propagation: G becomes the minimum over the 3x3 texels `step` apart, B the minimum of
//                 their distances + step, so the nearest occluder and the distance to the boundary spread
//                 from the edges (Valient & de Boer 2004: "repeated ... depends on the largest allowed penumbra radius").
//                 The paper steps one texel per pass; here the steps halve (2^(n-1), ..., 2, 1, each run
//                 twice, ping-pong, after one step-1 pass), jump flooding, so 2n + 1 passes reach
//                 2 (2^n - 1) + 1 texels instead of 2n + 1: the preprocessing over a 1024² map is the
//                 dominant cost on llvmpipe. B is a distance in texels (an upper bound on the Chebyshev
//                 distance) rather than the paper's accumulated inverse distance: the same information,
//                 compared directly with q.
//                 (4) The final pass: a shadowed receiver takes d2 from R, a lit one from G (none: fully
//                 lit); if the boundary is further than q, the point is in umbra or full light and takes the
//                 hard result (the early out, switchable by `EarlyOut` so its saving can be measured);
//                 otherwise q-disk PCF with the "penetrating disk" correction: an occluded sample C whose own
//                 disk (radius from C's occluder depth) does not contain P cannot hide any of the light from
//                 P, and counts as lit.
//   direct        without preprocessing (Valient & de Boer 2004, "Implementation without preprocessing"): a shadowed
//                 receiver takes d2 from its own map texel; a lit one first searches the disk of the largest
//                 radius for the largest d2 (the paper's "more correct" variant, not the minimum: the map
//                 holds back faces), then filters with the q that gives. No early out.
//
// Deviations, said here so they are not mistaken for the paper: the samples are the 32-point Poisson disk
// of pcf.fxh taken from a random start (the paper's noise-map rows, its "constant registers" alternative),
// rotated per texel; the random start and angle come from a fixed-seed noise texture addressed in light
// space (pcf.fx: the pattern stays on the surface) rather than in screen space.
//
// `-D FD_SHOW_EARLY_OUT=1`: the final pass writes 1 where the pixel took the early out (umbra or full light
// decided from the preprocessed map, or no occluder near), 0 where it filtered, for the share of early-out
// pixels (tests/effects/test_soft_shadow_effects.cpp, docs/techniques/soft-shadows.md).
// Measurement hooks SHADOWFX_SHADOW_MAP_SIZE, SHADOWFX_VISIBILITY (docs/scoring.md, "Measurement hooks").

#include "include/lighting.fxh"
#include "include/shadowmap.fxh"
#include "include/pcf.fxh"
#include "include/blur.fxh"
#include "include/shadowscene.fxh"
#include "include/light_size.fxh"

#ifdef SHADOWFX_SHADOW_MAP_SIZE
#define SHADOW_MAP_SIZE SHADOWFX_SHADOW_MAP_SIZE
#else
#define SHADOW_MAP_SIZE 1024
#endif

float Script : STANDARDSGLOBAL
<
    string UIWidget = "none";
    string ScriptClass = "scene";
    string ScriptOrder = "standard";
    string ScriptOutput = "color";
    string Script = "Technique=preprocessed;";
> = 0.8;

// [SECTION] Tweakables
// Eq. 2's a: map texels of disk area per sample.
float TexelsPerSample
<
    string UIWidget = "slider";
    string UIName = "Disk texels per sample (a)";
    float UIMin = 0.5;
    float UIMax = 16.0;
> = 4.0;

int MaxSamples
<
    string UIWidget = "slider";
    string UIName = "Largest sample count";
    int UIMin = 1;
    int UIMax = 32;
> = 32;

float MaxRadiusTexels
<
    string UIWidget = "slider";
    string UIName = "Largest disk radius (texels)";
    float UIMin = 1.0;
    float UIMax = 32.0;
> = 16.0;

float MinRadiusTexels
<
    string UIWidget = "slider";
    string UIName = "Smallest disk radius (texels)";
    float UIMin = 0.0;
    float UIMax = 4.0;
> = 1.0;

// Jump-flooding loops, two passes each with steps 2^(n-1) ... 1: the boundary distance and nearest
// occluder reach 2 (2^n - 1) + 1 texels, which must cover MaxRadiusTexels for the early out to be right.
int PropagationLoops
<
    string UIWidget = "slider";
    string UIName = "Propagation loops (2 passes each)";
    int UIMin = 0;
    int UIMax = 6;
> = 3;

int PropagationIndex <string UIWidget = "None";> = 0;  // LoopGetIndex

// Depth jump (in linear [0, 1] light depth) that marks a hard shadow boundary in the map.
float EdgeThreshold
<
    string UIWidget = "slider";
    string UIName = "Edge detection threshold";
    float UIMin = 0.0;
    float UIMax = 0.1;
> = 0.01;

bool EarlyOut
<
    string UIName = "Early out in umbra and full light";
> = true;

float Bias
<
    string UIWidget = "slider";
    string UIName = "Depth bias (linear depth)";
    float UIMin = 0.0;
    float UIMax = 0.02;
    float UIStep = 0.0002;
> = 0.002;

// Extra bias per texel of receiver slope, for the test against back faces (an open surface's own faces
// towards the light are tested at its tangent plane instead; see Occludes).
float SlopeBias
<
    string UIWidget = "slider";
    string UIName = "Slope bias per texel";
    float UIMin = 0.0;
    float UIMax = 4.0;
> = 1.0;

float2 ShadowMapSize <string UIWidget = "none";> = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};

// Depth, nearest occluder, distance to the boundary: clear to "nothing here, no boundary near".
float4 NoOccluderFar <string UIWidget = "none";> = {1.0, 1.0, 1.0e4, 1.0};

// [SECTION] Textures and samplers
texture DiskMap : RENDERCOLORTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "A32B32G32R32F";
    string UIWidget = "None";
>;

texture DiskMapTemp : RENDERCOLORTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "A32B32G32R32F";
    string UIWidget = "None";
>;

sampler DiskMapSampler = sampler_state
{
    texture = <DiskMap>;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MipFilter = NONE;
    MinFilter = POINT;
    MagFilter = POINT;
};

sampler DiskMapTempSampler = sampler_state
{
    texture = <DiskMapTemp>;
    AddressU = CLAMP;
    AddressV = CLAMP;
    MipFilter = NONE;
    MinFilter = POINT;
    MagFilter = POINT;
};

texture ShadowDepth : RENDERDEPTHSTENCILTARGET
<
    float2 Dimensions = {SHADOW_MAP_SIZE, SHADOW_MAP_SIZE};
    string Format = "D24S8";
    string UIWidget = "None";
>;

// The noise map: per texel a random start into the Poisson disk (R) and a rotation angle (G); fixed seed.
texture DiskNoise
<
    string Procedural = "noise";
    int Seed = 2;
    float2 Dimensions = {64, 64};
    string Format = "A32B32G32R32F";
    string UIWidget = "None";
>;

sampler DiskNoiseSampler = sampler_state
{
    texture = <DiskNoise>;
    AddressU = WRAP;
    AddressV = WRAP;
    MipFilter = NONE;
    MinFilter = POINT;
    MagFilter = POINT;
};

// [SECTION] Depth conversions
// Eq. 4: light-view depth mapped linearly onto [0, 1] between the light's near and far planes.
float LinearDepth(float clipDepth)
{
    float nearDepth = LightViewDepth(0.0);
    return (LightViewDepth(clipDepth) - nearDepth) / (LightViewDepth(1.0) - nearDepth);
}

// World distance along the light's axis of a linear depth difference.
float WorldDepthRange()
{
    return LightViewDepth(1.0) - LightViewDepth(0.0);
}

// q in texels for a receiver at linear depth `receiver` and an occluder at `occluder` (Valient & de Boer 2004, eq. 1),
// at the receiver's texel scale, clamped to [MinRadiusTexels, MaxRadiusTexels].
float DiskRadiusTexels(float receiver, float occluder, float receiverViewDepth, float texelsPerUnit)
{
    float d2World = max(receiver - occluder, 0.0) * WorldDepthRange();
    float q = PenumbraRadiusWorld(receiverViewDepth, receiverViewDepth - d2World, LightRadius) * texelsPerUnit;
    return clamp(q, MinRadiusTexels, MaxRadiusTexels);
}

// [SECTION] Back-face map and preprocessing
// VFACE > 0 on triangles facing the light (D3D's clockwise front faces): only open objects draw them.
float4 BackFaceDepthPS(DepthVertexOutput IN, float face : VFACE) : COLOR
{
    return float4(LinearDepth(LightDepth(IN)), 1.0, 1.0e4, face > 0 ? 1.0 : 0.0);
}

// Pass 1: edges of the depth map are the hard shadow boundaries. Edge texels get the nearest occluder (the
// 3x3 minimum depth: the detector also marks texels beside the real edge) and distance 0.
float4 DetectEdgesPS(BufferVertex IN) : COLOR
{
    float2 texel = 1.0 / ShadowMapSize;
    float centre = tex2D(DiskMapSampler, IN.UV).x;
    float lowest = centre;
    float highest = centre;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            float d = tex2D(DiskMapSampler, IN.UV + float2(x, y) * texel).x;
            lowest = min(lowest, d);
            highest = max(highest, d);
        }
    bool edge = highest - lowest > EdgeThreshold;
    float frontFace = tex2D(DiskMapSampler, IN.UV).w;
    return edge ? float4(centre, lowest, 0.0, frontFace) : float4(centre, 1.0, 1.0e4, frontFace);
}

// Passes 2..: the nearest occluder and the distance to the boundary spread `step` texels further.
float4 Propagate(sampler2D source, float2 uv, float step)
{
    float2 texel = step / ShadowMapSize;
    float4 centre = tex2D(source, uv);
    float occluder = centre.y;
    float distance = centre.z;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            float4 n = tex2D(source, uv + float2(x, y) * texel);
            occluder = min(occluder, n.y);
            distance = min(distance, n.z + step);
        }
    return float4(centre.x, occluder, distance, centre.w);
}

float JumpStep()
{
    return exp2(float(PropagationLoops - 1 - PropagationIndex));
}

float4 PropagateOnceFromTempPS(BufferVertex IN) : COLOR
{
    return Propagate(DiskMapTempSampler, IN.UV, 1.0);
}

float4 PropagateFromTempPS(BufferVertex IN) : COLOR
{
    return Propagate(DiskMapTempSampler, IN.UV, JumpStep());
}

float4 PropagateFromMapPS(BufferVertex IN) : COLOR
{
    return Propagate(DiskMapSampler, IN.UV, JumpStep());
}

// [SECTION] Final pass
struct DiskSampling
{
    float2 uv;
    float receiver;          // linear depth, biased (constant and slope)
    ReceiverPlane plane;     // its tangent plane, for the open objects' front faces
    float receiverViewDepth;
    float texelsPerUnit;
    float start;             // random start into the Poisson disk
    float2x2 rotation;
};

DiskSampling MakeSampling(SceneVertexOutput IN)
{
    DiskSampling s;
    s.uv = ShadowMapUV(IN.LP);
    float clipDepth = IN.LP.z / IN.LP.w;
    s.receiver = LinearDepth(clipDepth) - Bias - SlopeBias * ReceiverSlope(IN) / ShadowMapSize.x;
    s.plane = TangentReceiverPlane(LightViewProjectionMatrix, IN.LP, normalize(IN.WNormal), ShadowMapSize, 0.0);
    s.receiverViewDepth = LightViewDepth(clipDepth);
    s.texelsPerUnit = TexelsPerWorldUnit(IN.LP, ShadowMapSize.x);
    float2 noise = tex2D(DiskNoiseSampler, s.uv * ShadowMapSize / 64.0).xy;
    s.start = floor(noise.x * 32.0);
    float angle = 6.2831853 * noise.y;
    s.rotation = float2x2(cos(angle), sin(angle), -sin(angle), cos(angle));
    return s;
}

// Whether the map texel `texel` (depth in R, front-face mark in A), read at `uv`, is in front of the
// receiver: a back face against the biased receiver depth, an open object's front face against the
// receiver's tangent plane at the texel's centre less Bias.
bool Occludes(DiskSampling s, float4 texel, float2 uv)
{
    if (texel.w > 0.5)
        return texel.x < LinearDepth(PlaneDepthAt(s.plane, floor(uv * ShadowMapSize) + 0.5)) - Bias;
    return texel.x < s.receiver;
}

float2 DiskOffsetTexels(DiskSampling s, int i, float radius)
{
    return mul(kPoissonDisk[int(fmod(s.start + i, 32.0))], s.rotation) * radius;
}

// Eq. 2: ⌈π q² / a⌉ samples, at most MaxSamples.
int SampleCount(float q)
{
    return int(min(ceil(3.14159265 * q * q / TexelsPerSample), float(clamp(MaxSamples, 1, 32))));
}

// Lit fraction of the disk of radius q texels around the receiver, with the penetrating-disk correction.
float DiskVisibility(sampler2D map, DiskSampling s, float q)
{
    int n = SampleCount(q);
    float lit = 0;
    for (int i = 0; i < n; ++i) {
        float2 offset = DiskOffsetTexels(s, i, q);
        float2 uv = s.uv + offset / ShadowMapSize;
        float4 texel = tex2D(map, uv);
        float occluder = texel.x;
        bool occluded = Occludes(s, texel, uv);
        // C's own disk: radius from C's occluder as seen from the receiver's plane; P outside it: C lit.
        if (occluded && length(offset) > DiskRadiusTexels(s.receiver, occluder, s.receiverViewDepth,
                                                          s.texelsPerUnit))
            occluded = false;
        lit += occluded ? 0.0 : 1.0;
    }
    return lit / n;
}

// x: visibility, y: 1 where the early out decided it.
float2 PreprocessedVisibility(SceneVertexOutput IN)
{
    DiskSampling s = MakeSampling(IN);
    float4 texel = tex2D(DiskMapSampler, s.uv);
    float hard = Occludes(s, texel, s.uv) ? 0.0 : 1.0;
    float occluder = hard == 0.0 ? texel.x : texel.y;
    if (hard == 1.0 && texel.y >= 1.0)
        return float2(1.0, 1.0);  // no occluder anywhere near: full light
    float q = DiskRadiusTexels(s.receiver, occluder, s.receiverViewDepth, s.texelsPerUnit);
    if (EarlyOut && texel.z > q)
        return float2(hard, 1.0);  // the boundary is further than the disk: umbra or full light
    return float2(DiskVisibility(DiskMapSampler, s, q), 0.0);
}

float DirectVisibility(SceneVertexOutput IN)
{
    DiskSampling s = MakeSampling(IN);
    float4 own = tex2D(DiskMapSampler, s.uv);
    float occluder = own.x;
    if (!Occludes(s, own, s.uv)) {
        // Lit at the centre: the nearest-to-the-light occluder within the largest disk gives the largest d2.
        occluder = 1.0;
        bool found = false;
        int n = clamp(MaxSamples, 1, 32);
        for (int i = 0; i < n; ++i) {
            float2 uv = s.uv + DiskOffsetTexels(s, i, MaxRadiusTexels) / ShadowMapSize;
            float4 texel = tex2D(DiskMapSampler, uv);
            if (Occludes(s, texel, uv)) {
                occluder = min(occluder, texel.x);
                found = true;
            }
        }
        if (!found)
            return 1.0;
    }
    float q = DiskRadiusTexels(s.receiver, occluder, s.receiverViewDepth, s.texelsPerUnit);
    return DiskVisibility(DiskMapSampler, s, q);
}

float4 PreprocessedPS(SceneVertexOutput IN) : COLOR
{
    float2 result = PreprocessedVisibility(IN);
#ifdef FD_SHOW_EARLY_OUT
    return float4(result.yyy, 1);
#else
    return ShadeOrVisibility(IN, result.x);
#endif
}

float4 DirectPS(SceneVertexOutput IN) : COLOR
{
    return ShadeOrVisibility(IN, DirectVisibility(IN));
}

// [SECTION] Techniques
#define BACK_FACE_PASS                                                                                      \
    pass RenderBackFaces                                                                                    \
    <                                                                                                       \
        /* Light-pass culling keeps casters this far from a visible receiver (docs/measurement.md,  */     \
        /* "Leave-out"): the disk reaches MaxRadiusTexels, at most 32, plus one texel. */                   \
        float FilterReachTexels = 33;                                                                       \
        string Script = "RenderColorTarget0=DiskMap;"                                                       \
                        "RenderDepthStencilTarget=ShadowDepth;"                                             \
                        "RenderPort=light0;"                                                                \
                        "ClearSetColor=NoOccluderFar;"                                                      \
                        "ClearSetDepth=ClearDepth;"                                                         \
                        "Clear=Color;"                                                                      \
                        "Clear=Depth;"                                                                      \
                        "Draw=Geometry;";                                                                   \
        bool CullClosedOnly = true;                                                                         \
    >                                                                                                       \
    {                                                                                                       \
        CullMode = CW;                                                                                      \
        ZEnable = true;                                                                                     \
        ZWriteEnable = true;                                                                                \
        VertexShader = compile vs_3_0 RenderDepthVS(mul(WorldMatrix, mul(LightViewMatrix, LightProjectionMatrix))); \
        PixelShader = compile ps_3_0 BackFaceDepthPS();                                                     \
    }

// A full-map pass; the map-sized depth target stays bound so the viewport is the map's (effects/vsm.fx).
#define MAP_PASS(NAME, TARGET, PS)                                                                          \
    pass NAME                                                                                               \
    <                                                                                                       \
        string Script = "RenderColorTarget0=" #TARGET ";"                                                   \
                        "RenderDepthStencilTarget=ShadowDepth;"                                             \
                        "RenderPort=light0;"                                                                \
                        "Draw=Buffer;";                                                                     \
    >                                                                                                       \
    {                                                                                                       \
        CullMode = None;                                                                                    \
        ZEnable = false;                                                                                    \
        ZWriteEnable = false;                                                                               \
        VertexShader = compile vs_3_0 BufferVS();                                                           \
        PixelShader = compile ps_3_0 PS();                                                                  \
    }

#define SCENE_PASS(PS)                                                                                      \
    pass RenderScene                                                                                        \
    <                                                                                                       \
        string Script = "RenderColorTarget0=;"                                                              \
                        "RenderDepthStencilTarget=;"                                                        \
                        "RenderPort=;"                                                                      \
                        "ClearSetColor=ClearColor;"                                                         \
                        "ClearSetDepth=ClearDepth;"                                                         \
                        "Clear=Color;"                                                                      \
                        "Clear=Depth;"                                                                      \
                        "Draw=Geometry;";                                                                   \
    >                                                                                                       \
    {                                                                                                       \
        CullMode = CCW;                                                                                     \
        ZEnable = true;                                                                                     \
        ZWriteEnable = true;                                                                                \
        VertexShader = compile vs_3_0 RenderSceneVS(mul(LightViewMatrix, LightProjectionMatrix));           \
        PixelShader = compile ps_3_0 PS();                                                                  \
    }

technique preprocessed
<
    // Measured by `shadowfx stress` (docs/measurement.md, "shadowfx stress"); reported as xfail.
    string StressExpectedFailures = "behind-ordinary [uniform]: the minimum disk radius (MinRadiusTexels) "
                                    "softens edges by texels spanning up to 1,000 pixels here";
    // Edges are detected into the temporary map, a step-1 pass brings them back, then each loop
    // propagates there and back: the final map is DiskMap again.
    string Script = "Pass=RenderBackFaces; Pass=DetectEdges; Pass=PropagateOnce;"
                    "LoopByCount=PropagationLoops; LoopGetIndex=PropagationIndex;"
                    "Pass=PropagateToTemp; Pass=PropagateToMap; LoopEnd=;"
                    "Pass=RenderScene;";
    string ExpectScenes = "dual-l,teapot";
    // measured 0.044 % on dual-l, 0.114 % on teapot (hard truth); 0.089 / 0.157 % against the area-light
    // truth's classification (--area-radius 2)
    float ExpectMisclassifiedBelow = 0.25;
    // penumbra MAE 0.086 on dual-l, 0.200 on teapot (320x240, bench --area-radius 2)
    string ExpectPenumbraMaeBelow = "dual-l=0.13, teapot=0.31";
    float ExpectAreaRadius = 2;  // the light size the penumbra bound holds for
    int ExpectMapSize = 1024;
>
{
    BACK_FACE_PASS
    MAP_PASS(DetectEdges, DiskMapTemp, DetectEdgesPS)
    MAP_PASS(PropagateOnce, DiskMap, PropagateOnceFromTempPS)
    MAP_PASS(PropagateToTemp, DiskMapTemp, PropagateFromMapPS)
    MAP_PASS(PropagateToMap, DiskMap, PropagateFromTempPS)
    SCENE_PASS(PreprocessedPS)
}

technique direct
<
    // Measured by `shadowfx stress` (docs/measurement.md, "shadowfx stress"); reported as xfail.
    string StressExpectedFailures = "behind-ordinary [uniform]: the minimum disk radius (MinRadiusTexels) "
                                    "softens edges by texels spanning up to 1,000 pixels here";
    string Script = "Pass=RenderBackFaces; Pass=RenderScene;";
    string ExpectScenes = "dual-l,teapot";
    // measured 0.044 % on dual-l, 0.114 % on teapot (hard truth); 0.089 / 0.169 % against the area-light
    // truth's classification (--area-radius 2)
    float ExpectMisclassifiedBelow = 0.26;
    // penumbra MAE 0.085 on dual-l, 0.201 on teapot (320x240, bench --area-radius 2)
    string ExpectPenumbraMaeBelow = "dual-l=0.13, teapot=0.31";
    float ExpectAreaRadius = 2;  // the light size the penumbra bound holds for
    int ExpectMapSize = 1024;
>
{
    BACK_FACE_PASS
    SCENE_PASS(DirectPS)
}
