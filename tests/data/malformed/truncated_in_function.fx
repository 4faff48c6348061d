// Ends inside a function body.
float4 PS() : COLOR
{
    return float4(1, 0, 0, 1);
