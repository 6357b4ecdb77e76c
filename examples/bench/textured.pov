// The six primitives of the paper's Figure 6 on a checkered floor under a
// rectangular area light of 9 x 9 points. It stresses texture edges: the
// checker's edges cross pixels that one object covers, which object-space
// adaptive sampling does not see as edges, and they shrink toward the back
// wall. (A checker to the horizon, where no method converges, is another test.)
// It renders the same way in POV-Ray 3.7; LightN sets the light's points:
//   asos render examples/bench/textured.pov -o textured.png
//   povray +Iexamples/bench/textured.pov +Otextured-pov.png +W320 +H240 Declare=LightN=9
// scripts/bench-scenes.sh times both against a converged POV-Ray render.
#version 3.7;
#ifndef (LightN) #declare LightN = 9; #end
#ifndef (LightAdaptive) #declare LightAdaptive = 1; #end

global_settings { assumed_gamma 1.0 }
background { color rgb <0.6, 0.7, 0.85> }
camera { location <0, 4.5, -9> look_at <0, 0.6, 0.6> angle 55 }
light_source {
  <0.5, 9, -1.5>, color rgb 1
  area_light <3, 0, 0>, <0, 0, 3>, LightN, LightN
  adaptive LightAdaptive
}

#declare Matte = finish { ambient 0.12 diffuse 0.75 }
plane { y, 0
  pigment { checker color rgb 0.9, color rgb <0.25, 0.3, 0.4> scale 0.8 rotate y*20 }
  finish { Matte } }
box { <-30, 0, 7>, <30, 12, 7.2> pigment { color rgb <0.8, 0.78, 0.72> } finish { Matte } }

sphere { <-3, 1.9, 1.6>, 0.9 pigment { color rgb <0.85, 0.2, 0.15> } finish { Matte phong 0.5 } }
polygon {
  7, <1, 0>, <0.5, 0.866>, <-0.5, 0.866>, <-1, 0>, <-0.5, -0.866>, <0.5, -0.866>, <1, 0>
  rotate <70, 0, 0> translate <0, 1.6, 1.8>
  pigment { checker color rgb <0.15, 0.7, 0.7>, color rgb 0.95 scale 0.25 } finish { Matte } }
disc { <3, 1.5, 1.6>, <0.3, 1, -0.4>, 1.0, 0.35 pigment { color rgb <0.6, 0.3, 0.8> } finish { Matte } }
box { <-0.7, 0, -0.7>, <0.7, 1.2, 0.7> rotate <0, 25, 0> translate <-3, 0, -1.6>
  pigment { brick color rgb 0.85, color rgb <0.6, 0.2, 0.15> scale 0.06 } finish { Matte } }
cone { <0, 0, -1.6>, 0.9, <0, 1.8, -1.6>, 0 pigment { color rgb <0.95, 0.7, 0.1> } finish { Matte } }
cylinder { <2.2, 1.0, -1.9>, <3.8, 1.4, -1.3>, 0.35
  pigment { checker color rgb <0.2, 0.7, 0.3>, color rgb 0.9 scale 0.2 } finish { Matte } }
