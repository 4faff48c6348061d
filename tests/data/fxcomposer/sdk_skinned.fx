//-----------------------------------------------------------------------------
// An effect in the style of the DirectX 9 SDK samples: D3DCOLOR integer constants, arrays sized by
// static const int and constant expressions, skinning inputs (BLENDWEIGHT, BLENDINDICES), COLOR0 and
// PSIZE/FOG inputs, a centroid-interpolated texture coordinate, a matrix varying, vs_1_1/ps_2_0
// profiles, and a preshader that calls the effect's own function.
//-----------------------------------------------------------------------------

static const int MAX_MATRICES = 4;
static const int NUM_LIGHTS = 2;

int BackgroundColor = 0xff202080;     // D3DCOLOR: above INT_MAX, HLSL wraps it
int Mask = 0xFFFFFFFF;

float4x3 mWorldMatrixArray[MAX_MATRICES * 2 - MAX_MATRICES] : WORLDMATRIXARRAY;
float4x4 mViewProj : VIEWPROJECTION;
float4x4 mWorld : WORLD;

float3 lightDir[NUM_LIGHTS] = { {0.0f, -1.0f, 0.2f}, {0.5f, -0.5f, -0.5f} };
float4 MaterialAmbient : MATERIALAMBIENT = {0.1f, 0.1f, 0.1f, 1.0f};
float4 MaterialDiffuse : MATERIALDIFFUSE = {0.8f, 0.8f, 0.8f, 1.0f};

float Brightness = 0.5f;

// Host-evaluated from uniforms and literals, as D3DX's preshader did.
float gain(float b, float scale)
{
    return saturate(b * scale + 0.25f);
}

struct VS_INPUT
{
    float4 Pos          : POSITION;
    float4 BlendWeights : BLENDWEIGHT;
    float4 BlendIndices : BLENDINDICES;
    float3 Normal       : NORMAL;
    float4 Color        : COLOR0;
    float3 Tex0         : TEXCOORD0;
    float  Size         : PSIZE;
    float  Fog          : FOG;
};

struct VS_OUTPUT
{
    float4 Pos     : POSITION;
    float4 Diffuse : COLOR0;
    float2 Tex0    : TEXCOORD0_centroid;
    float3x3 Basis : TEXCOORD1;
};

float3 Diffuse(float3 Normal)
{
    float CosTheta = 0;
    for (int i = 0; i < NUM_LIGHTS; i++)
        CosTheta += max(0.0f, dot(Normal, -normalize(lightDir[i])));
    return CosTheta;
}

VS_OUTPUT VShade(VS_INPUT i, uniform int NumBones, uniform float Gain)
{
    VS_OUTPUT o;
    float3 Pos = mul(i.Pos, mWorld).xyz;
    float3 Normal = normalize(mul(i.Normal, (float3x3)mWorld));
    float LastWeight = 1.0f - i.BlendWeights.x * (NumBones - 1) * 0.0f;
    o.Pos = mul(float4(Pos.xyz, 1.0f), mViewProj);
    o.Diffuse.xyz = MaterialAmbient.xyz + Gain * Diffuse(Normal) * MaterialDiffuse.xyz * LastWeight;
    o.Diffuse.w = 1.0f;
    o.Tex0 = i.Tex0.xy;
    o.Basis = float3x3(Normal, Normal.yzx, Normal.zxy);
    return o;
}

float4 PShade(VS_OUTPUT i) : COLOR0
{
    float3 n = i.Basis[0];
    return float4(i.Diffuse.rgb * (0.75f + 0.25f * abs(n.y)), 1.0f);
}

VertexShader vsArray[2] = { compile vs_1_1 VShade(1, gain(Brightness, 1.5f)),
                            compile vs_2_0 VShade(2, gain(Brightness, 1.5f)) };

technique t0
{
    pass p0
    {
        VertexShader = (vsArray[1]);
        PixelShader  = compile ps_2_0 PShade();
        ZEnable = true;
        ZFunc = LessEqual;
        CullMode = None;
    }
}
