// The crackle pattern: POV-Ray's defaults, form, metric (a vector, its x
// kept), offset and solid in any order with the other modifiers, a
// declared crackle given more, and crackle as a normal's pattern.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Cells = pigment { crackle solid scale 0.3 }
sphere { 0, 1 pigment { crackle } }
sphere { x, 1 pigment { crackle form <1, 0, 0> metric <3, 7, 7> offset 0.25 color_map { [0 rgb 0] [1 rgb 1] } } }
sphere { y, 1 pigment { crackle turbulence 0.3 metric 1 frequency 2 solid noise_generator 3 } }
sphere { z, 1 pigment { Cells offset -0.1 } }
sphere { -x, 1 pigment { Cells crackle } }
sphere { -y, 1 normal { crackle 0.6 form <-0.5, 0.2, 0.5> metric 2.5 scale 0.2 } }
