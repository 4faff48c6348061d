// Ends inside a pass, in the middle of a state assignment.
float4 VS(float4 p : POSITION) : POSITION { return p; }
float4 PS() : COLOR { return 1; }
technique t
{
    pass p
    {
        ZEnable =
