// Multisample arrays: no resource shadowfx creates.
Texture2DMSArray<float4, 4> Samples;
