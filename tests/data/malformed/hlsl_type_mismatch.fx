// A float3 returned where a float4 is declared, assigned to a struct.
struct S { float4 a; };
float4 VS(float4 p : POSITION) : POSITION { S s = p; return s.a; }
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
