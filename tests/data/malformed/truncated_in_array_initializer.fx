// Ends inside a braced initializer.
float4 Color = {1, 0, 0,
