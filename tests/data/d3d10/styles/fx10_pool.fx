// In the style of FX10 effects written for an effect pool: a shared cbuffer, shader variables (one of
// them NULL), a group, uppercase SV_TARGET.
shared cbuffer cbShared { float4x4 g_mViewProj; float3 g_vEyePt; };
float4x4 g_mWorld;
float g_fTime;
struct VS_IN { float3 Pos : POSITION; float3 Norm : NORMAL; };
struct PS_IN { float4 Pos : SV_POSITION; float3 Norm : TEXCOORD0; float3 ViewDir : TEXCOORD1; };
PS_IN VSMain(VS_IN In) { PS_IN o; float4 wp = mul(float4(In.Pos, 1), g_mWorld); o.Pos = mul(wp, g_mViewProj); o.Norm = mul(In.Norm, (float3x3)g_mWorld); o.ViewDir = g_vEyePt - wp.xyz; return o; }
float4 PSMain(PS_IN In) : SV_TARGET { float r = saturate(dot(normalize(In.Norm), normalize(In.ViewDir))); return float4(r, r * abs(sin(g_fTime)), 1 - r, 1); }
GeometryShader gsNull = NULL;
VertexShader vsMain = CompileShader(vs_4_0, VSMain());
PixelShader psMain = CompileShader(ps_4_0, PSMain());
fxgroup Scene
{
    technique10 Facing
    {
        pass P0 { SetVertexShader(vsMain); SetGeometryShader(gsNull); SetPixelShader(psMain); }
    }
}
