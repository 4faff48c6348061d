// SetBlendState without its blend factor and sample mask.
BlendState Opaque { BlendEnable[0] = FALSE; };
technique11 T { pass { SetBlendState(Opaque); } }
