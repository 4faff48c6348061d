// A constant index past the end of a state-object array: fxc refuses it when compiling.
RasterizerState Fills[2] { { FillMode = SOLID; }, { FillMode = WIREFRAME; } };
float4 VS(float4 p : POSITION) : SV_Position { return p; }
float4 PS() : SV_Target { return 1; }
technique11 Drawn
{
    pass
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetPixelShader(CompileShader(ps_5_0, PS()));
        SetRasterizerState(Fills[2]);
    }
}
