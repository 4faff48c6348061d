// A missing semicolon after a parameter.
float Bias = 0.01
float Other = 1;
