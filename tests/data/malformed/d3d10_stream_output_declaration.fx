// A stream-output declaration whose second entry masks components that are not contiguous.
struct P { float3 pos : POSITION; float3 vel : NORMAL; };
P VS(P p) { return p; }
[maxvertexcount(1)] void GS(point P input[1], inout PointStream<P> stream) { stream.Append(input[0]); }
GeometryShader gsStreamOut = ConstructGSWithSO(CompileShader(gs_4_0, GS()), "POSITION.xyz; NORMAL.xz");
technique10 Advance { pass p0 { SetVertexShader(CompileShader(vs_4_0, VS())); SetGeometryShader(gsStreamOut); SetPixelShader(NULL); } }
