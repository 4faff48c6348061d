// Characters HLSL does not have.
float Bias = 0.01 @ $;
