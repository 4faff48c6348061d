// Ends inside a sampler_state block.
texture T;
sampler S = sampler_state { Texture = <T>; MinFilter = LINEAR;
