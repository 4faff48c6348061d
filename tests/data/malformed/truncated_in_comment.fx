// Ends inside a block comment.
float Bias = 0.01;
/* never closed
