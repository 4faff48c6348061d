// A hull shader without [patchconstantfunc]: nothing would compute its tessellation factors.
struct V { float3 p : POSITION; };
struct C { float e[3] : SV_TessFactor; float i : SV_InsideTessFactor; };
struct D { float4 p : SV_Position; };
V VS(float3 p : POSITION) { V v; v.p = p; return v; }
[domain("tri")]
[partitioning("integer")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(3)]
V HS(InputPatch<V, 3> ip, uint i : SV_OutputControlPointID) { return ip[i]; }
[domain("tri")]
D DS(C c, float3 uvw : SV_DomainLocation, const OutputPatch<V, 3> op) { D d; d.p = float4(op[0].p * uvw.x, 1); return d; }
float4 PS() : SV_Target { return 1; }
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetHullShader(CompileShader(hs_5_0, HS()));
                       SetDomainShader(CompileShader(ds_5_0, DS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
