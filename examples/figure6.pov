// The arrangement of the paper's Figure 6 (Genetti & Gordon 1993, "Results"):
// the six primitives asos implements (sphere, polygon, disc, box, cone,
// cylinder) above a ground plane, and the shadows each light casts. Light
// chooses the light, as the four quarters of the figure do:
//   0  an antialiased point light above the objects       (upper left)
//   1  a spherical light at the same place                (lower left)
//   2  a linear light parallel to the x axis              (upper right)
//   3  a rectangular light in the x-z plane               (lower right)
// Every light has the same colour (its total power), so the four images
// share their brightness. Render, e.g.:
//   asos render examples/figure6.pov -D Light=3 -o figure6_rect.png -W 640 -H 480
//   asos render examples/figure6.pov -D Light=3 --light-method grid --light-samples 8 -o grid.png
// docs/lights.md explains the light forms.
#version 3.7;
#ifndef (Light) #declare Light = 3; #end

global_settings { assumed_gamma 1.0 ambient_light 1 }
background { color rgb <0.6, 0.7, 0.85> }
camera { location <0, 7.5, -9> look_at <0, 0.2, 0.6> angle 52 }

#declare LightPosition = <0.5, 9, -1.5>;
#declare LightColour = color rgb 1;
#if (Light = 0)
  light_source { LightPosition, LightColour }
#elseif (Light = 1)
  light_source { LightPosition, LightColour area_light <2.4, 0, 0>, <0, 0, 2.4>, 8, 8 circular orient }
#elseif (Light = 2)
  light_source { LightPosition, LightColour area_light <4, 0, 0>, <0, 0, 0>, 16, 1 }
#else
  light_source { LightPosition, LightColour area_light <3, 0, 0>, <0, 0, 3>, 8, 8 }
#end

#declare Matte = finish { ambient 0.12 diffuse 0.75 }
plane { y, 0 pigment { color rgb 0.9 } finish { Matte } }

// Back row, floating: the sphere, the polygon (a hexagon) and the disc.
sphere { <-3, 1.9, 1.6>, 0.9 pigment { color rgb <0.85, 0.2, 0.15> } finish { Matte } }
polygon {
  7, <1, 0>, <0.5, 0.866>, <-0.5, 0.866>, <-1, 0>, <-0.5, -0.866>, <0.5, -0.866>, <1, 0>
  scale 1.0 rotate <70, 0, 0> translate <0, 1.6, 1.8>
  pigment { color rgb <0.15, 0.7, 0.7> } finish { Matte }
}
disc { <3, 1.5, 1.6>, <0.3, 1, -0.4>, 1.0, 0.35 pigment { color rgb <0.6, 0.3, 0.8> } finish { Matte } }

// Front row: the box and the cone stand on the ground, the cylinder floats.
box { <-0.7, 0, -0.7>, <0.7, 1.2, 0.7> rotate <0, 25, 0> translate <-3, 0, -1.6>
  pigment { color rgb <0.2, 0.4, 0.85> } finish { Matte } }
cone { <0, 0, -1.6>, 0.9, <0, 1.8, -1.6>, 0 pigment { color rgb <0.95, 0.7, 0.1> } finish { Matte } }
cylinder { <2.2, 1.0, -1.9>, <3.8, 1.4, -1.3>, 0.35 pigment { color rgb <0.2, 0.7, 0.3> } finish { Matte } }
