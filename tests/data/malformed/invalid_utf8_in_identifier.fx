// Invalid UTF-8 inside an identifier.
float Bi€€s = 0.01;
