// A blend state handed to SetRasterizerState.
BlendState Additive { BlendEnable[0] = TRUE; SrcBlend = ONE; DestBlend = ONE; };
technique11 T { pass { SetRasterizerState(Additive); } }
