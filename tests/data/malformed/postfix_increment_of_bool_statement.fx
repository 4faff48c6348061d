// A post-increment of a bool as a statement: glslang's HLSL front end dropped the statement without a
// word and compiled the rest.
float4 PS() : COLOR {
    bool lit = false;
    lit++;
    return lit ? 1 : 0;
}
technique t { pass p { PixelShader = compile ps_3_0 PS(); } }
