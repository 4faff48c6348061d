// glslang 12 (HLSL front end): SIGSEGV in HlslParseContext::handleFunctionArgument on a post-decrement of
// a value that is not an l-value, as a call argument.
float4 PS() : COLOR { return normalize(float3(1, 1, 1)--).xyzz; }
technique t { pass p { PixelShader = compile ps_3_0 PS(); } }
