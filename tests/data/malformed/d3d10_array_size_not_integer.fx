// ArraySize must be a whole number of elements, and only arrays have one.
Texture2DArray Layers < int ArraySize = 2.5; >;
Texture2D Plain < int ArraySize = 2; >;
