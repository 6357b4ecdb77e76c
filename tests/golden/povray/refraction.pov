// Cross-check of interiors: a glass sphere of ior 1.5 (refraction, total
// internal reflection at its rim) and a box of ior 1.33 whose inside fades
// to amber, over a checker floor and its shadows through them. Rendered by
// tests/unit/render_golden_test.cpp with one ray per pixel; POV-Ray's
// reference by scripts/update-goldens.sh (povray -A).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 45 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { checker rgb 1 rgb <0.2, 0.3, 0.4> scale 0.5 } }
sphere { <-0.8, 1, 0>, 1 pigment { rgbf <0.9, 1, 0.9, 0.95> } finish { phong 0.8 phong_size 80 } interior { ior 1.5 } }
box { <0.5, 0.01, -0.5>, <1.8, 1.5, 0.3> pigment { rgbt <1, 0.8, 0.6, 0.9> } interior { ior 1.33 fade_distance 1 fade_power 2 fade_color rgb <0.8, 0.3, 0.1> } }
cylinder { <0, 0, 2>, <0, 2, 2>, 0.3 pigment { rgb <0.8, 0.2, 0.2> } }
