// An effect written for an application, as D3DX9 samples wrote theirs: no SAS script, no semantics, no
// render targets of its own. The application sets every matrix, creates the shadow map, draws
// RenderShadow into it from the light and RenderScene into its frame (app_shadow.json says so).
float4x4 g_mWorld;
float4x4 g_mViewProj;
float4x4 g_mLightViewProj;
float3 g_vLightPos;
float4 g_vColor = float4(1, 1, 1, 1);
float g_fAmbient = 0.2;
float g_fBias = 0.002;
texture g_txShadow;

sampler2D g_samShadow = sampler_state {
    Texture = <g_txShadow>;
    MinFilter = Point;
    MagFilter = Point;
    AddressU = Clamp;
    AddressV = Clamp;
};

void VertShadow(float4 pos : POSITION, out float4 oPos : POSITION, out float2 depth : TEXCOORD0) {
    oPos = mul(mul(pos, g_mWorld), g_mLightViewProj);
    depth = oPos.zw;
}

float4 PixShadow(float2 depth : TEXCOORD0) : COLOR {
    return depth.x / depth.y;
}

void VertScene(float4 pos : POSITION, float3 normal : NORMAL, out float4 oPos : POSITION,
               out float3 worldPos : TEXCOORD0, out float3 worldNormal : TEXCOORD1,
               out float4 lightPos : TEXCOORD2) {
    float4 world = mul(pos, g_mWorld);
    oPos = mul(world, g_mViewProj);
    worldPos = world.xyz;
    worldNormal = mul(normal, (float3x3)g_mWorld);
    lightPos = mul(world, g_mLightViewProj);
}

float4 PixScene(float3 worldPos : TEXCOORD0, float3 worldNormal : TEXCOORD1,
                float4 lightPos : TEXCOORD2) : COLOR {
    float2 uv = 0.5 * lightPos.xy / lightPos.w + float2(0.5, 0.5);
    uv.y = 1.0 - uv.y;
    float lit = tex2D(g_samShadow, uv).r + g_fBias < lightPos.z / lightPos.w ? 0.0 : 1.0;
    float ndotl = saturate(dot(normalize(worldNormal), normalize(g_vLightPos - worldPos)));
    return float4(g_vColor.rgb * (g_fAmbient + (1.0 - g_fAmbient) * ndotl * lit), 1.0);
}

technique RenderShadow {
    pass p0 {
        VertexShader = compile vs_2_0 VertShadow();
        PixelShader = compile ps_2_0 PixShadow();
    }
}

technique RenderScene {
    pass p0 {
        VertexShader = compile vs_2_0 VertScene();
        PixelShader = compile ps_2_0 PixScene();
    }
}
