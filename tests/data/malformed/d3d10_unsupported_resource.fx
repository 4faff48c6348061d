// A read-write 3D texture: nothing in an effect sizes its texture, so shadowfx runs none.
RWTexture3D<float4> Volume;
