// Benchmark scene "penumbra" (docs/performance.md): soft shadows under each
// kind of area light, where the eye's sampling is easy and the light's is
// not. Three groups on a floor, each under its own light:
//   * left, a rectangle light 2 x 2 over a sphere, a box and a disc on a post;
//   * middle, a linear light 3 long over a cylinder, a cone and a polygon;
//   * right, a round light 1.5 across (`circular orient`) over a sphere and a box;
// and a thin occluder: a wire 0.04 thick running across all three groups
// above the floor, whose shadow is all penumbra (no point of the floor under
// it is in full shadow). LightN sets the grid's points along each side.
//   asos render examples/bench/penumbra.pov -W 320 -H 240 -o penumbra.png
//   asos-bench accuracy examples/bench/penumbra.pov -o build/accuracy
#version 3.7;
#ifndef (LightN) #declare LightN = 5; #end
global_settings { assumed_gamma 1.0 }
background { color rgb <0.5, 0.6, 0.75> }
camera { location <0, 5.5, -7.5> look_at <0, 0.4, 0.6> angle 72 }
#declare Matte = finish { ambient 0.1 diffuse 0.8 }

light_source { <-4.5, 3.5, 2.5>, color rgb 0.4 area_light <2, 0, 0>, <0, 0, 2>, LightN, LightN }
light_source { <0, 3.5, 3>, color rgb 0.4 area_light <3, 0, 0>, <0, 0, 0>, LightN, 1 }
light_source { <4.5, 3.5, 2.5>, color rgb 0.4 area_light <1.5, 0, 0>, <0, 0, 1.5>, LightN, LightN circular orient }

plane { y, 0 pigment { color rgb 0.85 } finish { Matte } }
// Left: rectangle light.
sphere { <-5.2, 0.7, 0.5>, 0.7 pigment { color rgb <0.85, 0.3, 0.2> } finish { Matte } }
box { <-4.2, 0, -0.9>, <-3.2, 1.1, 0.1> rotate y * 20 pigment { color rgb <0.3, 0.6, 0.9> } finish { Matte } }
cylinder { <-4, 0, 1.5>, <-4, 0.9, 1.5>, 0.05 pigment { color rgb 0.6 } finish { Matte } }
disc { <-4, 0.9, 1.5>, <0.2, 1, 0.1>, 0.6 pigment { color rgb <0.9, 0.8, 0.3> } finish { Matte } }
// Middle: linear light.
cylinder { <-0.9, 0, -0.5>, <-0.9, 1.4, -0.5>, 0.35 pigment { color rgb <0.4, 0.8, 0.4> } finish { Matte } }
cone { <0.9, 0, -0.2>, 0.6, <0.9, 1.5, -0.2>, 0 pigment { color rgb <0.9, 0.6, 0.2> } finish { Matte } }
polygon { 5, <-0.6, 0>, <0.6, 0>, <0.6, 1.2>, <-0.6, 1.2>, <-0.6, 0> rotate y * 30 translate <0, 0, 1.4>
  pigment { color rgb <0.7, 0.4, 0.8> } finish { Matte } }
// Right: round light.
sphere { <4, 0.6, -0.6>, 0.6 pigment { color rgb <0.3, 0.5, 0.95> } finish { Matte } }
box { <4.6, 0, 0.6>, <5.6, 0.5, 1.6> rotate y * -15 pigment { color rgb <0.95, 0.95, 0.9> } finish { Matte } }
// The thin occluder, across all three.
cylinder { <-7, 1.6, -1.6>, <7, 1.2, -1.2>, 0.02 pigment { color rgb 0.2 } finish { Matte } }
