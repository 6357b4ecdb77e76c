// pigment_map and average: entries of colours, declared pigments and
// patterns written without braces (their transforms their own, relative to
// the outer pigment), a nested map, the comma after the value, a declared
// pigment with a map given more transforms, average with weights and
// without, a directive among an entry's items, and a colour map replacing
// a declared pigment's pigment map.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Spots = pigment { bozo color_map { [0 rgb 0] [1 rgb <1, 0.5, 0>] } scale 0.2 }
#declare Sky = pigment {
  gradient y
  pigment_map {
    [0.1 rgb <0.8, 0.7, 0.8>]
    [0.3, Spots scale 2 rotate 10 * z]
    [0.6 wood pigment_map { [0 rgb 1] [1 checker rgb 0, rgb <0, 0, 1> scale 0.1] } turbulence 0.2]
  }
  triangle_wave frequency 2
}
sphere { 0, 1 pigment { Sky } }
sphere { x, 1 pigment { Sky scale 3 } }
sphere { y, 1 pigment { average pigment_map { [1 Spots] [2, rgbf <1, 1, 1, 0.5>] [Spots rotate 90 * y] } translate z } }
sphere { z, 1 pigment { radial pigment_map { [0 rgb 0] [1 #if (true) rgb 1 #else rgb 0.5 #end] } } }
sphere { -x, 1 pigment { Sky color_map { [0 rgb 0] [1 rgb 1] } } }
// A declared pigment_map, shared by a gradient and an average.
#declare Map = pigment_map { [0 rgb 1] [0.5, Spots] [1 rgb <0, 0, 1>] }
sphere { 2 * x, 1 pigment { gradient x pigment_map { Map } } }
sphere { 2 * y, 1 pigment { average pigment_map { Map } } }
// checker and brick of pigments (POV-Ray's pigment list), the second left out.
sphere { -y, 1 pigment { checker pigment { Spots } pigment { Sky scale 0.5 } scale 2 } }
sphere { -z, 1 pigment { brick pigment { rgb 1 } brick_size 2 } }
