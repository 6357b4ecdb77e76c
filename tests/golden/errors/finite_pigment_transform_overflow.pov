// A pigment's transforms that overflow.
sphere { 0, 1 pigment { checker scale 1e300 scale 1e300 } }
