// blur.fxh: a separable box blur for full-screen (Draw=Buffer) passes: run it once along x into a second
// target and once along y back, ping-pong, for a taps x taps box filter at 2 x taps texel reads. Used to
// pre-filter variance shadow maps (Lehőcz 2007: "a separable convolution filter to blur the shadow edges").
//
//   pass BlurX < string Script = "RenderColorTarget0=Temp; Draw=Buffer;"; > { PixelShader = compile
//       ps_3_0 BlurXPS(); }   // with  float4 BlurXPS(BufferVertex IN) : COLOR
//       { return BoxBlur(SourceSampler, IN.UV, float2(1.0 / width, 0), Taps); }
#ifndef SHADOWFX_BLUR_FXH
#define SHADOWFX_BLUR_FXH

// What a Draw=Buffer quad hands the pixel shader: clip-space position, and TEXCOORD0 (0,0) at the top-left.
struct BufferVertex
{
    float4 Position : POSITION;
    float2 UV       : TEXCOORD0;
};

BufferVertex BufferVS(float4 Position : POSITION, float2 UV : TEXCOORD0)
{
    BufferVertex OUT;
    OUT.Position = Position;
    OUT.UV = UV;
    return OUT;
}

// Mean of `taps` texels (odd: 1, 3, 5, ...; clamped to 1..31) centred on `uv`, stepping by `step` (one texel
// along the blur's axis, in texture coordinates). The source should be point-sampled with CLAMP addressing.
float4 BoxBlur(sampler2D source, float2 uv, float2 step, int taps)
{
    int radius = clamp(taps, 1, 31) / 2;
    float4 sum = 0;
    for (int i = -radius; i <= radius; ++i)
        sum += tex2D(source, uv + i * step);
    return sum / (2 * radius + 1);
}

#endif
