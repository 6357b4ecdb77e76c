plane { y, 0 pigment { crackle scale 2 } }
