// The map patterns with their modifiers, colour maps (declared, replaced,
// POV-Ray's older two-colour entries), hollow, and global noise_generator.
#version 3.7;
global_settings { assumed_gamma 1.0 noise_generator 1 }
#declare Stone = color_map { [0 rgb 0.9] [0.8 rgb 0.4] [1 rgb 0.1] }
#declare Veined = pigment { marble turbulence 0.8 color_map { Stone } scale 2 }
sphere { 0, 1 pigment { gradient <0, 2, 0> color_map { [0 rgb 0] [0.5, 1 color rgb <1, 0, 0> color rgb 1] } } hollow }
sphere { x, 1 pigment { Veined omega 0.4 lambda 3 octaves 12 } hollow off }
sphere { y, 1 pigment { wood turbulence <0.1, 0.3, 0> ramp_wave frequency 2 phase 0.5 noise_generator 3 } hollow (1 > 2) }
sphere { z, 1 pigment { agate agate_turb 0.5 rotate x * 90 } }
sphere { -x, 1 pigment { radial color_map { Stone } sine_wave } }
box { 0, 1 pigment { bozo } }
box { 1, 2 pigment { spotted triangle_wave } }
box { 2, 3 pigment { granite scale 0.5 } }
box { 3, 4 pigment { leopard } }
box { 4, 5 pigment { onion translate < -1 0 0.5 > } }  // commas between components are optional
plane { y, -1 pigment { rgb 1 turbulence 0.5 color_map { Stone } } }
