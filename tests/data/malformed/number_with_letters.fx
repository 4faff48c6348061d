// A number run into letters.
float Bias = 12abc;
