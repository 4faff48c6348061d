// An annotation block without its closing '>'.
float Bias < string UIName = "Bias"; = 0.01;
