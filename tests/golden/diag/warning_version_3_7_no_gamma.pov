// A POV-Ray 3.7 scene without assumed_gamma: it is 1.0, with POV-Ray's warning.
#version 3.7;
sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }
