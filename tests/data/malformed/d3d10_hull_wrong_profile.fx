// A domain-shader profile compiled for the hull stage.
struct V { float3 p : POSITION; };
struct C { float e[3] : SV_TessFactor; float i : SV_InsideTessFactor; };
struct D { float4 p : SV_Position; };
V VS(float3 p : POSITION) { V v; v.p = p; return v; }
C PCF(InputPatch<V, 3> ip) { C c; c.e[0] = c.e[1] = c.e[2] = c.i = 2; return c; }
[domain("tri")]
[partitioning("integer")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(3)]
[patchconstantfunc("PCF")]
V HS(InputPatch<V, 3> ip, uint i : SV_OutputControlPointID) { return ip[i]; }
[domain("tri")]
D DS(C c, float3 uvw : SV_DomainLocation, const OutputPatch<V, 3> op) { D d; d.p = float4(op[0].p * uvw.x, 1); return d; }
float4 PS() : SV_Target { return 1; }
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetHullShader(CompileShader(ds_5_0, HS()));
                       SetDomainShader(CompileShader(ds_5_0, DS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
