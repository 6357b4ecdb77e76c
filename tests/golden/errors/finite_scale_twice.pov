// Two scales that together overflow.
sphere { 0, 1 scale 1e200 scale 1e200 }
