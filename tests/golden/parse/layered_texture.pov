// Layered textures: declared (each texture over the one before), moved as one,
// and on an object (a texture over the one it has; a pigment then changes the
// top layer). Only the bottom layer must be opaque.
#version 3.7;
#declare Varnish =
  texture { pigment { wood color_map { [0 rgb <0.8, 0.5, 0.2>] [1 rgb <0.5, 0.25, 0.1>] } } }
  texture { pigment { rgbf <1, 0.9, 0.7, 0.8> } finish { phong 0.8 } }
box { 0, 1 texture { Varnish scale 0.2 } }
sphere { 0, 1 pigment { rgb <1, 0, 0> } translate x
  texture { pigment { checker rgbt 1 rgb 0 } } finish { specular 0.5 } }
