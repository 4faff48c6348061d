// 3ds Max effects name their textures by Windows paths, some with a backslash left unescaped (`\D`, no
// escape): fxc kept the character, and the path reads as written, with a warning at that backslash.
#define BASE_MAP "C:\\Users\\max\Desktop\\maps\\base.tga"

texture BaseTexture < string ResourceName = BASE_MAP; string Folder = "maps\detail"; string Quoted = "a\"b\\c"; >;

float4x4 WorldViewProjection : WORLDVIEWPROJECTION;

struct VS_OUT { float4 Position : POSITION; float3 Normal : TEXCOORD0; };
VS_OUT VS(float3 p : POSITION, float3 n : NORMAL)
{
    VS_OUT o;
    o.Position = mul(float4(p, 1), WorldViewProjection);
    o.Normal = n;
    return o;
}
float4 PS(VS_OUT i) : COLOR { return float4(normalize(i.Normal) * 0.5 + 0.5, 1); }

technique Main
{
    pass P
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
    }
}
