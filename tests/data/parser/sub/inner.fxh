float innerValue = 2;
