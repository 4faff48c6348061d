// A pass written by a macro, for macro_from_header.fx.
#define SHADED_PASS pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); \
                             ZFunc = Sometimes; }
