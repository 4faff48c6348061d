// A cbuffer that never closes.
cbuffer PerFrame
{
    float4x4 View;
