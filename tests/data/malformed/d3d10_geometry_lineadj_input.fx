// A geometry shader that takes lines with adjacency: a mesh's triangles define no line strips to continue.
struct V { float4 p : SV_Position; };
V VS(float3 p : POSITION) { V v; v.p = float4(p, 1); return v; }
[maxvertexcount(4)]
void GS(lineadj V pt[4], inout LineStream<V> s) { s.Append(pt[1]); s.Append(pt[2]); }
float4 PS() : SV_Target { return 1; }
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetGeometryShader(CompileShader(gs_5_0, GS()));
                       SetPixelShader(CompileShader(ps_5_0, PS())); } }
