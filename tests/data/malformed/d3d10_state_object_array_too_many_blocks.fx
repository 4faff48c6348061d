// A state-object array given more blocks than it has elements.
BlendState Blends[1] = { { BlendEnable[0] = FALSE; }, { BlendEnable[0] = TRUE; } };
