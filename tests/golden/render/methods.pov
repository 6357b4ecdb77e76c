// Golden render of asos (tests/unit/render_golden_test.cpp): the six
// primitives on a checkered plane under a point light, one of them a mirror,
// rendered by every method (asos, single, grid, jitter, adaptive, am1).
// The reference PNGs beside it are rewritten only by scripts/update-goldens.sh.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.55, 0.7, 0.9> }
camera { location <0, 4.5, -10> look_at <0, 0.9, 1> angle 48 }
light_source { <-8, 12, -10>, color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.85, color rgb 0.3 } finish { diffuse 0.8 } }
sphere { <-3, 1, 0>, 1 pigment { color rgb <0.85, 0.15, 0.12> } finish { phong 0.6 reflection 0.3 } }
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8> rotate <0, 30, 0> pigment { color rgb <0.2, 0.45, 0.85> } }
cone { <3, 0, 0>, 1, <3, 2.2, 0>, 0 pigment { color rgb <0.95, 0.7, 0.1> } finish { phong 0.6 } }
cylinder { <-3, 0, 3.5>, <-3, 1.6, 3.5>, 0.8 pigment { color rgb <0.2, 0.7, 0.3> } }
disc { <0, 1.3, 3.5>, <0, 0.5, -1>, 1.2, 0.45 pigment { color rgb <0.65, 0.3, 0.8> } }
polygon {
  7, <1, 0>, <0.5, 0.866>, <-0.5, 0.866>, <-1, 0>, <-0.5, -0.866>, <0.5, -0.866>, <1, 0>
  scale 1.1 rotate <-20, -15, 0> translate <3, 1.3, 3.5>
  pigment { color rgb <0.1, 0.75, 0.75> }
}
