// brick_size and mortar modify a brick pigment only (POV-Ray: "cannot be
// used with non-brick"); a brick with a zero side would divide by zero.
#declare Plain = pigment { rgb 1 }
sphere { 0, 1 pigment { checker mortar 0.2 } }
sphere { 0, 1 pigment { rgb 1 brick_size 2 } }
sphere { 0, 1 pigment { Plain mortar 0.2 } }
sphere { 0, 1 pigment { brick brick_size <1, 0, 1> } }
sphere { 0, 1 pigment { brick rgb 1 rgb 0 rgb 0.5 } }
