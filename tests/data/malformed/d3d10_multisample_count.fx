// Texture2DMS's sample count is its second template argument, 1..32.
Texture2DMS<float4, 64> Samples;
// A render target must say how many samples it holds.
Texture2DMS<float4> Target : RENDERCOLORTARGET;
