// Control characters between tokens.
floatBias = 0.01;
