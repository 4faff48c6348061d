// A post-decrement of a value that is no l-value, as a call's argument: glslang's HLSL front end crashed
// on it.
float4 PS() : COLOR { return normalize(float3(1, 1, 1)--).xyzz; }
technique t { pass p { PixelShader = compile ps_3_0 PS(); } }
