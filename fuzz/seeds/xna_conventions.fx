// A fuzzing seed of the forms XNA's and MonoGame's effects use and the legalization rewrites: numbered
// lights, a bare sampler, a bone palette, a per-instance matrix input, `*` of constant matrices.
float4x4 World;
float4x4 WorldViewProj;
float3 DirLight0Direction;
float3 DirLight0DiffuseColor;
float3 DirLight1Direction;
float3 g_LightDir;
float3 g_LightDir2;
float4x3 Bones[4];
sampler2D Texture : register(s0);
static const float2x2 S = {1, 2, 3, 4};
static const float2x2 T = float2x2(5, 6, 7, 8) * S;
static const int N = (int)(S * T)._m11;
struct VSOut { float4 Position : POSITION; float2 Uv : TEXCOORD0; float3 Lit : TEXCOORD1; };
VSOut VS(float4 p : POSITION, float3 n : NORMAL, float2 uv : TEXCOORD0, int4 indices : BLENDINDICES0,
         float4 weights : BLENDWEIGHT0, float4x4 instance : TEXCOORD1) {
    float4x3 skin = Bones[indices.x] * weights.x + Bones[indices.y] * weights.y;
    const float2x2 local = float2x2(1, 0, 0, 1);
    float2x2 k = local * S;
    VSOut o;
    o.Position = mul(mul(float4(mul(p, skin), 1), transpose(instance)), WorldViewProj);
    float spread[N];
    for (int i = 0; i < N; i++) spread[i] = i;
    o.Uv = uv * k[1] + spread[1];
    float3 normal = normalize(mul(n, (float3x3)World));
    o.Lit = DirLight0DiffuseColor * max(0, dot(normal, -DirLight0Direction)) +
            max(0, dot(normal, -DirLight1Direction)) + max(0, dot(normal, g_LightDir + g_LightDir2));
    return o;
}
float4 PS(float2 Uv : TEXCOORD0, float3 Lit : TEXCOORD1) : COLOR { return tex2D(Texture, Uv) * float4(Lit, 1); }
technique BasicEffect { pass { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
