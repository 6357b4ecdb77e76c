plane { y, 0 pigment { granite scale 2 } }
