// A vertex-shader profile compiled for the geometry stage.
struct V { float4 p : SV_Position; };
V VS(float3 p : POSITION) { V v; v.p = float4(p, 1); return v; }
[maxvertexcount(3)]
void GS(triangle V tri[3], inout TriangleStream<V> s) { s.Append(tri[0]); }
float4 PS() : SV_Target { return 1; }
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetGeometryShader(CompileShader(vs_5_0, GS()));
                       SetPixelShader(CompileShader(ps_5_0, PS())); } }
