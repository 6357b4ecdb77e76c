// POV-Ray's order inside a pigment: an optional declared pigment, one colour
// or pattern, then transforms. POV-Ray rejects each of these.
#declare Red = pigment { rgb <1, 0, 0> }
sphere { 0, 1 pigment { rgb 1 rgb 0 } }
sphere { 0, 1 pigment { scale 2 rgb 1 } }
sphere { 0, 1 pigment { checker rgb 1 rgb 0 rgb 0.5 } }
sphere { 0, 1 pigment { rgb 1 Red } }
