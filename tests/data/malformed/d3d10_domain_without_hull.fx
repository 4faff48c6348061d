// A domain shader in a pass without a hull shader: nothing would feed the tessellator.
struct V { float3 p : POSITION; };
struct C { float e[3] : SV_TessFactor; float i : SV_InsideTessFactor; };
struct D { float4 p : SV_Position; };
V VS(float3 p : POSITION) { V v; v.p = p; return v; }
[domain("tri")]
D DS(C c, float3 uvw : SV_DomainLocation, const OutputPatch<V, 3> op) { D d; d.p = float4(op[0].p * uvw.x, 1); return d; }
float4 PS() : SV_Target { return 1; }
technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); SetHullShader(NULL);
                       SetDomainShader(CompileShader(ds_5_0, DS())); SetPixelShader(CompileShader(ps_5_0, PS())); } }
