//--------------------------------------------------------------------------------------
// In the style of the DirectX SDK's DXUT samples: globals set by name, no semantics, uniform arguments.
//--------------------------------------------------------------------------------------
float4 g_MaterialAmbientColor = float4(0.2f, 0.2f, 0.2f, 1.0f);
float4 g_MaterialDiffuseColor = float4(0.8f, 0.7f, 0.6f, 1.0f);
int    g_nNumLights = 1;
float3 g_LightDir[3];
float4 g_LightDiffuse[3];
float4 g_LightAmbient = float4(0.1f, 0.1f, 0.1f, 1.0f);
Texture2D g_MeshTexture;
float    g_fTime;
float4x4 g_mWorld;
float4x4 g_mWorldViewProjection;

SamplerState MeshTextureSampler
{
    Filter = MIN_MAG_MIP_LINEAR;
    AddressU = Wrap;
    AddressV = Wrap;
};

struct VS_OUTPUT
{
    float4 Position   : SV_POSITION;
    float4 Diffuse    : COLOR0;
    float2 TextureUV  : TEXCOORD0;
};

VS_OUTPUT RenderSceneVS( float4 vPos : POSITION, float3 vNormal : NORMAL, float2 vTexCoord0 : TEXCOORD,
                         uniform int nNumLights, uniform bool bTexture, uniform bool bAnimate )
{
    VS_OUTPUT Output;
    float3 vNormalWorldSpace;
    float4 vAnimatedPos = vPos;
    if( bAnimate )
        vAnimatedPos += float4(vNormal, 0) * (sin(g_fTime+5.5)+0.5)*5;
    Output.Position = mul(vAnimatedPos, g_mWorldViewProjection);
    vNormalWorldSpace = normalize(mul(vNormal, (float3x3)g_mWorld));
    float3 vTotalLightDiffuse = float3(0,0,0);
    for(int i=0; i<nNumLights; i++ )
        vTotalLightDiffuse += g_LightDiffuse[i].rgb * max(0,dot(vNormalWorldSpace, g_LightDir[i]));
    Output.Diffuse.rgb = g_MaterialDiffuseColor.rgb * vTotalLightDiffuse +
                         g_MaterialAmbientColor.rgb * g_LightAmbient.rgb;
    Output.Diffuse.a = 1.0f;
    if( bTexture )
        Output.TextureUV = vTexCoord0;
    else
        Output.TextureUV = 0;
    return Output;
}

float4 RenderScenePS( VS_OUTPUT In, uniform bool bTexture ) : SV_Target
{
    float4 Output;
    if( bTexture )
        Output = g_MeshTexture.Sample(MeshTextureSampler, In.TextureUV) * In.Diffuse;
    else
        Output = In.Diffuse;
    return Output;
}

DepthStencilState EnableDepth
{
    DepthEnable = TRUE;
    DepthWriteMask = ALL;
    DepthFunc = LESS_EQUAL;
};

technique10 RenderSceneWithTexture1Light
{
    pass P0
    {
        SetVertexShader( CompileShader( vs_4_0, RenderSceneVS( 1, true, false ) ) );
        SetGeometryShader( NULL );
        SetPixelShader( CompileShader( ps_4_0, RenderScenePS( true ) ) );
        SetDepthStencilState( EnableDepth, 0 );
    }
}

technique10 RenderSceneNoTexture
{
    pass P0
    {
        SetVertexShader( CompileShader( vs_4_0, RenderSceneVS( 1, false, false ) ) );
        SetGeometryShader( NULL );
        SetPixelShader( CompileShader( ps_4_0, RenderScenePS( false ) ) );
    }
}
