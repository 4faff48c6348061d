// Scripts FX Composer warned about and ran anyway: a ClearSetColor naming no parameter, a Clear naming no
// buffer, and a RenderColorTarget naming a texture that is not a render target. Each command is left out
// with a warning, the commands around them stay; the pass draws the object into the frame, twice.
float Script : STANDARDSGLOBAL <
    string ScriptClass = "object";
    string ScriptOrder = "standard";
    string ScriptOutput = "color";
    string Script = "Technique=Main;";
> = 0.8;

float4x4 WvpXf : WorldViewProjection;
float4x4 WorldXf : World;

texture NotATarget < string ResourceName = "not_there.dds"; >;

float4 VS(float4 p : POSITION, float3 n : NORMAL, out float3 normal : TEXCOORD0) : POSITION
{
    normal = mul(n, (float3x3)WorldXf);
    return mul(p, WvpXf);
}

float4 PS(float3 normal : TEXCOORD0) : COLOR
{
    return float4(normalize(normal) * 0.5 + 0.5, 1);
}

technique Main <
    string Script = "Pass=p0; ClearSetColor=ClearColour;"
                    "Clear=;"
                    "RenderColorTarget0=NotATarget;"
                    "Pass=p0;";
> {
    pass P0 < string Script = "Draw=Geometry;"; >
    {
        VertexShader = compile vs_3_0 VS();
        PixelShader = compile ps_3_0 PS();
        ZEnable = true;
        CullMode = None;
    }
}
