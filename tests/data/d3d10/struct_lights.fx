// Lights and a material held in structs, in the style of Frank Luna's D3D11 book effects (2012,
// "Introduction to 3D Game Programming with DirectX 11", LightHelper.fx): the application fills each
// member by name; nothing has a semantic. Three directional lights in an array, a point light and a
// material; the pixel shader sums each light's ambient, diffuse and Phong specular terms as his does.

struct DirectionalLight {
    float4 Ambient;
    float4 Diffuse;
    float4 Specular;
    float3 Direction;
    float pad;
};

struct PointLight {
    float4 Ambient;
    float4 Diffuse;
    float4 Specular;
    float3 Position;
    float Range;
    float3 Att;
    float pad;
};

struct Material {
    float4 Ambient;
    float4 Diffuse;
    float4 Specular;  // w = SpecPower
    float4 Reflect;
};

cbuffer cbPerFrame {
    DirectionalLight gDirLights[3];
    PointLight gPointLight;
    float3 gEyePosW;
};

cbuffer cbPerObject {
    float4x4 gWorld;
    float4x4 gWorldInvTranspose;
    float4x4 gWorldViewProj;
    Material gMaterial;
};

void ComputeDirectionalLight(Material mat, DirectionalLight L, float3 normal, float3 toEye,
                             out float4 ambient, out float4 diffuse, out float4 spec) {
    ambient = mat.Ambient * L.Ambient;
    diffuse = 0;
    spec = 0;
    float3 lightVec = -L.Direction;  // the light vector aims opposite the direction the light travels
    float diffuseFactor = dot(lightVec, normal);
    [flatten] if (diffuseFactor > 0.0f) {
        float3 v = reflect(-lightVec, normal);
        float specFactor = pow(max(dot(v, toEye), 0.0f), mat.Specular.w);
        diffuse = diffuseFactor * mat.Diffuse * L.Diffuse;
        spec = specFactor * mat.Specular * L.Specular;
    }
}

void ComputePointLight(Material mat, PointLight L, float3 pos, float3 normal, float3 toEye,
                       out float4 ambient, out float4 diffuse, out float4 spec) {
    ambient = 0;
    diffuse = 0;
    spec = 0;
    float3 lightVec = L.Position - pos;
    float d = length(lightVec);
    if (d > L.Range) return;
    lightVec /= d;
    ambient = mat.Ambient * L.Ambient;
    float diffuseFactor = dot(lightVec, normal);
    [flatten] if (diffuseFactor > 0.0f) {
        float3 v = reflect(-lightVec, normal);
        float specFactor = pow(max(dot(v, toEye), 0.0f), mat.Specular.w);
        diffuse = diffuseFactor * mat.Diffuse * L.Diffuse;
        spec = specFactor * mat.Specular * L.Specular;
    }
    float att = 1.0f / dot(L.Att, float3(1.0f, d, d * d));
    diffuse *= att;
    spec *= att;
}

struct VertexIn {
    float3 PosL : POSITION;
    float3 NormalL : NORMAL;
};

// Luna names the world position POSITION beside SV_POSITION; TEXCOORD0 keeps this file to the bindings.
struct VertexOut {
    float4 PosH : SV_POSITION;
    float3 PosW : TEXCOORD0;
    float3 NormalW : NORMAL;
};

VertexOut VS(VertexIn vin) {
    VertexOut vout;
    vout.PosW = mul(float4(vin.PosL, 1.0f), gWorld).xyz;
    vout.NormalW = mul(vin.NormalL, (float3x3)gWorldInvTranspose);
    vout.PosH = mul(float4(vin.PosL, 1.0f), gWorldViewProj);
    return vout;
}

float4 PS(VertexOut pin, uniform bool usePointLight) : SV_Target {
    pin.NormalW = normalize(pin.NormalW);
    float3 toEyeW = normalize(gEyePosW - pin.PosW);
    float4 ambient = 0, diffuse = 0, spec = 0;
    float4 A, D, S;
    [unroll] for (int i = 0; i < 3; ++i) {
        ComputeDirectionalLight(gMaterial, gDirLights[i], pin.NormalW, toEyeW, A, D, S);
        ambient += A;
        diffuse += D;
        spec += S;
    }
    if (usePointLight) {
        ComputePointLight(gMaterial, gPointLight, pin.PosW, pin.NormalW, toEyeW, A, D, S);
        ambient += A;
        diffuse += D;
        spec += S;
    }
    float4 litColor = ambient + diffuse + spec;
    litColor.a = gMaterial.Diffuse.a;
    return litColor;
}

technique11 DirectionalOnly {
    pass P0 {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_5_0, PS(false)));
    }
}

technique11 WithPointLight {
    pass P0 {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_5_0, PS(true)));
    }
}
