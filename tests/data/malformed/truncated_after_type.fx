// Ends after a type name.
float4x4
