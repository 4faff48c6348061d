// Ends inside a parameter's annotation block.
float4x4 World : WORLD < string UIName = "World";
