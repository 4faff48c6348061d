// A statement in a shader without its ';': glslang names the next line's token; the error stands after
// the statement that lacks it.
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR
{
    float3 color = float3(1, 0, 0)
    return float4(color, 1);
}
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
