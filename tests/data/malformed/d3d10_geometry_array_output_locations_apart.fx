// A geometry shader's array output of twelve free-named elements: POINTS10 sorts between POINTS1 and
// POINTS2, so the elements cannot take the consecutive varying locations GL links an array at.
struct V { float4 pos : SV_Position; };
struct G { float4 pos : SV_Position; float4 points[12] : POINTS; };
V VS(float4 p : POSITION) { V v; v.pos = p; return v; }
[maxvertexcount(3)] void GS(triangle V input[3], inout TriangleStream<G> stream) {
    for (int i = 0; i < 3; ++i) { G g = (G)0; g.pos = input[i].pos; stream.Append(g); }
}
float4 PS(float4 pos : SV_Position) : SV_Target { return 1; }
technique10 T { pass p0 { SetVertexShader(CompileShader(vs_4_0, VS())); SetGeometryShader(CompileShader(gs_4_0, GS())); SetPixelShader(CompileShader(ps_4_0, PS())); } }
