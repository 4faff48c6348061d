// Overloads of one name, neither with as many uniform parameters as the compile expression's arguments.
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
float4 PS(uniform float a) : COLOR { return a; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(1, 2); } }
