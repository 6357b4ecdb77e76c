// A brick pattern with a zero brick size.
sphere { 0, 1 pigment { brick rgb 0, rgb 1 brick_size 0 } }
