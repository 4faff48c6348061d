// mul() of a one-component vector and a matrix (a fuzzer's find): glslang's HLSL front end crashed on it.
float4x4 World : World;

float4 VS(float4 P : POSITION, float1 Depth : TEXCOORD0) : POSITION {
    return P + mul(Depth, (float3x3)World).xyzz;
}

technique t { pass p { VertexShader = compile vs_3_0 VS(); } }
