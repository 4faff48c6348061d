// Ends in the middle of a compile expression.
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_3_0
