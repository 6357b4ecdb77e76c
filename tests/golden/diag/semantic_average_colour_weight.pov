// POV-Ray reads a colour at the start of an average entry as its weight,
// and refuses it: the weight must be written before a colour.
#declare Red = rgb <1, 0, 0>;
sphere { 0, 1 pigment { average pigment_map { [1 rgb 0] [Red] } } }
