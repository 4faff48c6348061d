// Invalid UTF-8 bytes where a declaration should be.
float Bias = 0.01;
Ã(ÿþ float Other = 1;
