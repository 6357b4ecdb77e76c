// Golden render of asos (tests/unit/render_golden_test.cpp): a cone (capped, truncated) and an open pointed cone.
// The reference PNGs beside it are rewritten only by scripts/update-goldens.sh.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.55, 0.7, 0.9> }
camera { location <0, 2.4, -5> look_at <0, 0.7, 0> angle 40 }
light_source { <-4, 7, -5>, color rgb 1 }
plane { y, 0 pigment { color rgb 0.75 } finish { diffuse 0.8 } }
cone { <-0.9, 0, 0>, 0.7, <-0.9, 1.6, 0>, 0.2 pigment { color rgb <0.95, 0.7, 0.1> } finish { phong 0.6 } }
cone { <0.9, 0, 0>, 0.6, <0.9, 1.5, 0>, 0 open pigment { color rgb <0.9, 0.4, 0.1> } }
