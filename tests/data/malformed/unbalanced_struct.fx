// A struct without its closing brace.
struct VertexOut
{
    float4 Position : POSITION;
    float2 UV : TEXCOORD0;

technique t { }
