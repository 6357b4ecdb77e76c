// The first scene of the manual (docs/manual/getting-started.md): a red ball
// on a checkered floor under one light.
//   asos render examples/first.pov -o first.png --stats --aov samples=first-samples.png
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.6, 0.75, 0.95> }
camera { location <0, 1.5, -4> look_at <0, 0.8, 0> angle 50 }
light_source { <-4, 6, -5>, color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.9, color rgb 0.35 } }
sphere { <0, 1, 0>, 1
  pigment { color rgb <0.9, 0.15, 0.1> }
  finish { phong 0.6 }
}
