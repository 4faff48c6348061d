// A type's name post-incremented where a value is returned (a fuzzer's find): glslang's HLSL front end
// crashed on it.
float4 PS() : COLOR { return float++ + float4(0.5, 0.5, 0.5, 1); }
technique t { pass p { PixelShader = compile ps_3_0 PS(); } }
