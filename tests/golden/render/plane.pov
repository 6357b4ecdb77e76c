// Golden render of asos (tests/unit/render_golden_test.cpp): a checkered
// plane to the horizon and a second plane crossing it (an interpenetration
// edge that no silhouette shows).
// The reference PNGs beside it are rewritten only by scripts/update-goldens.sh.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.55, 0.7, 0.9> }
camera { location <0, 2.4, -5> look_at <0, 0.7, 0> angle 40 }
light_source { <-4, 7, -5>, color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.85, color rgb 0.3 } finish { diffuse 0.8 } }
plane { <-1, 0.15, -0.3>, -1.1 pigment { color rgb <0.3, 0.6, 0.9> } }
