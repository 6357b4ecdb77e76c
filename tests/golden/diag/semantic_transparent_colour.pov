// POV-Ray makes a surface whose pigment colour has filter or transmit see
// through; asos renders opaque surfaces only, so anything but zero is refused
// (zero is accepted, as in POV-Ray's include files' rgbt <r, g, b, 0>).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare Glass = rgbf <1, 1, 1, 0.9>;
sphere { 0, 1 pigment { rgbt <0.5, 0.6, 0.7, 0> } }
sphere { 0, 1 pigment { color red 1 filter 0 transmit 0 } }
sphere { 0, 1 pigment { rgbf <1, 1, 1, 0.5> } }
sphere { 0, 1 pigment { Glass } }
sphere { 0, 1 pigment { color 0.5 } }
sphere { 0, 1 pigment { rgb 1 transmit 0.3 } }
plane { y, 0 pigment { checker rgb 1 rgbft <0, 0, 0, 0.5, 0.5> } }
plane { y, 0 pigment { brick rgbt 0.2 } }
