// Golden render of asos (tests/unit/render_golden_test.cpp): a disc with a hole, standing, and a flat disc.
// The reference PNGs beside it are rewritten only by scripts/update-goldens.sh.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.55, 0.7, 0.9> }
camera { location <0, 2.4, -5> look_at <0, 0.7, 0> angle 40 }
light_source { <-4, 7, -5>, color rgb 1 }
plane { y, 0 pigment { color rgb 0.75 } finish { diffuse 0.8 } }
disc { <-0.5, 1.1, 0.5>, <0, 0.5, -1>, 1.0, 0.4 pigment { color rgb <0.65, 0.3, 0.8> } }
disc { <1.2, 0.3, -0.6>, y, 0.5 pigment { color rgb <0.9, 0.5, 0.2> } }
