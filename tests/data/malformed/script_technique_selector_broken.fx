// A technique selector with no technique after its '?'.
bool Soft = true;
float Script : STANDARDSGLOBAL < string Script = "Technique=Soft?;"; > = 0.8;
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
