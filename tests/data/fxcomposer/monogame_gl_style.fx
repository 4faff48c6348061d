// An effect in the style of MonoGame ports built for OpenGL or Direct3D 9: the macros declare a sampler whose
// Texture state names a texture that nothing declares (MonoGame's effect compiler named the sampler's
// texture parameter after it), in a sampler block written without `= sampler_state`.
#define BEGIN_DECLARE_TEXTURE(Name, index) \
    sampler Name##Sampler : register(s##index) \
    { \
        Texture = (Name);
#define END_DECLARE_TEXTURE }
#define SAMPLE_TEXTURE(Name, texCoord) tex2D(Name##Sampler, texCoord)

float4x4 worldViewProj : WorldViewProjection;
float4x4 world : World;

BEGIN_DECLARE_TEXTURE(diffuseTexture, 0)
    AddressU = Wrap;
    AddressV = Wrap;
    MinFilter = Linear;
END_DECLARE_TEXTURE;

struct VertexOutput
{
    float4 pos : POSITION;
    float3 normal : TEXCOORD0;
    float2 texCoord : TEXCOORD1;
};

VertexOutput VS_Diffuse(float4 pos : POSITION, float3 normal : NORMAL, float2 texCoord : TEXCOORD0)
{
    VertexOutput o;
    o.pos = mul(pos, worldViewProj);
    o.normal = mul(normal, (float3x3)world);
    o.texCoord = texCoord;
    return o;
}

float4 PS_Diffuse(VertexOutput i) : COLOR
{
    float3 n = normalize(i.normal);
    float3 light = float3(1.0, 0.55, 0.25) * saturate(dot(n, normalize(float3(0.5, 1.0, 0.3)))) +
                   float3(0.15, 0.45, 1.0) * saturate(dot(n, normalize(float3(-0.6, 0.2, -0.8))));
    return SAMPLE_TEXTURE(diffuseTexture, i.texCoord) * float4(light + 0.05, 1);
}

technique Diffuse
{
    pass P0
    {
        VertexShader = compile vs_3_0 VS_Diffuse();
        PixelShader = compile ps_3_0 PS_Diffuse();
    }
}
