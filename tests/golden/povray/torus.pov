// Cross-check with POV-Ray 3.7 (tests/unit/render_golden_test.cpp): torus.
// A plain torus, one tilted, one squashed by a non-uniform scale and seen
// through its hole, a thin one with `sturm`, a fat (horn) one, and a box
// with a torus cut out (CSG: a torus' four crossings). References: povray -A.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.55, 0.7, 0.9> }
camera { location <0, 5, -10> look_at <0, 0.8, 1> right x*16/9 angle 50 }
light_source { <-6, 12, -10>, color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.85, color rgb 0.3 } finish { diffuse 0.8 } }
torus { 1.0, 0.35 pigment { color rgb <0.9, 0.4, 0.2> } finish { phong 0.6 } translate <-3.5, 0.35, 0> }
torus { 0.9, 0.3 pigment { color rgb <0.2, 0.6, 0.9> } rotate <60, 0, 20> translate <-0.6, 1.3, 0.5> }
torus { 1.0, 0.25 scale <1, 2, 0.6> rotate <-70, 30, 0> pigment { color rgb <0.3, 0.8, 0.3> } translate <2.0, 1.3, 1.5> }
torus { 1.2, 0.08 sturm pigment { color rgb <0.9, 0.9, 0.3> } rotate x*90 translate <0.6, 1.3, -2.2> }
torus { 0.5, 0.5 pigment { color rgb <0.8, 0.5, 0.9> } translate <4.0, 0.5, -1.8> }
difference {
  box { <-1, 0, -1>, <1, 0.8, 1> pigment { color rgb <0.85, 0.85, 0.8> } }
  torus { 0.6, 0.3 translate y*0.8 pigment { color rgb <0.9, 0.2, 0.2> } }
  rotate y*25 translate <-1.5, 0, -3.0>
}
