// An fxgroup whose closing brace is missing.
float4 VS(float3 p : POSITION) : SV_Position { return float4(p, 1); }
fxgroup Group
{
    technique11 T { pass { SetVertexShader(CompileShader(vs_5_0, VS())); } }
