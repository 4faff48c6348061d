// Ends inside a string literal.
string Name = "unfinished
