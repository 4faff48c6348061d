// A D3D11 full-screen pass in the modern style: no vertex buffer, the triangle from SV_VertexID; a
// luminance threshold with Texture2D.Load and GetDimensions.
Texture2D<float4> gInput;
cbuffer cbSettings { float gThreshold = 0.5f; float3 gTint = float3(1, 0.5, 0.25); };

struct VSOut { float4 pos : SV_Position; float2 uv : TEXCOORD0; };

VSOut FullscreenVS(uint id : SV_VertexID)
{
    VSOut o;
    o.uv = float2((id << 1) & 2, id & 2);
    o.pos = float4(o.uv * float2(2, -2) + float2(-1, 1), 0, 1);
    return o;
}

float4 ThresholdPS(VSOut i) : SV_Target
{
    uint w, h;
    gInput.GetDimensions(w, h);
    float3 c = gInput.Load(int3(i.uv * float2(w, h), 0)).rgb;
    float l = dot(c, float3(0.299, 0.587, 0.114));
    return float4((l > gThreshold ? c * gTint : gTint) * (0.5 + 0.5 * i.uv.x), 1);
}

technique11 Threshold
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_5_0, FullscreenVS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_5_0, ThresholdPS()));
    }
}
