// SetPixelShader given a vertex-shader variable.
float4 VS(float3 p : POSITION) : SV_Position { return float4(p, 1); }
VertexShader Vertex = CompileShader(vs_4_0, VS());
technique10 T { pass { SetVertexShader(Vertex); SetPixelShader(Vertex); } }
