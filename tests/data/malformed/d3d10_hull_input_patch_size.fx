// An input patch of sixteen control points (a bicubic patch): shadowfx draws a mesh's triangles as patches of three, or of four with a corner twice.
struct V { float3 p : POSITION; };
struct C { float e[4] : SV_TessFactor; float i[2] : SV_InsideTessFactor; };
struct D { float4 p : SV_Position; };
V VS(float3 p : POSITION) { V v; v.p = p; return v; }
C PCF(InputPatch<V, 16> ip) { C c; c.e[0] = c.e[1] = c.e[2] = c.e[3] = c.i[0] = c.i[1] = 2; return c; }
[domain("quad")]
[partitioning("integer")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(4)]
[patchconstantfunc("PCF")]
V HS(InputPatch<V, 16> ip, uint i : SV_OutputControlPointID) { return ip[i]; }
[domain("quad")]
D DS(C c, float2 uv : SV_DomainLocation, const OutputPatch<V, 4> op) { D d; d.p = float4(op[0].p * uv.x, 1); return d; }
float4 PS() : SV_Target { return 1; }
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetHullShader(CompileShader(hs_5_0, HS()));
                       SetDomainShader(CompileShader(ds_5_0, DS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
