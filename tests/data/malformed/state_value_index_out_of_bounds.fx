// A state's value indexes a parameter array by a constant outside its bounds: fxc refuses the effect when
// it compiles it, not only when the pass is applied.
int Refs[2] = {1, 2};
float4 VS(float4 p : POSITION) : SV_Position { return p; }
float4 PS() : SV_Target { return 1; }
DepthStencilState Stencil { StencilEnable = TRUE; };
technique10 T { pass P { SetVertexShader(CompileShader(vs_4_0, VS())); SetPixelShader(CompileShader(ps_4_0, PS())); SetDepthStencilState(Stencil, Refs[1 + 1]); } }
