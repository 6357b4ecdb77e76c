plane { y, 0 pigment { quilted scale 2 } }
