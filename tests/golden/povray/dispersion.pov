// Cross-check of dispersion: a glass prism-like box and a sphere of ior 1.5
// that split refracted light into bands of colour (dispersion 1.15 with
// POV-Ray's default 7 bands, and 1.08 with 4), over a striped floor; a
// dispersive sphere inside another shows a ray of one band refracted again.
// Rendered by tests/unit/render_golden_test.cpp with one ray per pixel;
// POV-Ray's reference by scripts/update-goldens.sh (povray -A).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2.5, -6> look_at <0, 0.8, 0> angle 45 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.9, 0.9, 1> }
plane { y, 0 pigment { gradient x color_map { [0.5 rgb 1] [0.5 rgb 0.05] } scale 0.25 } }
sphere { <-1, 1, 0>, 1 pigment { rgbf <1, 1, 1, 0.95> } interior { ior 1.5 dispersion 1.15 } }
box { <-0.6, -0.6, -0.6>, <0.6, 0.6, 0.6> rotate <35, 40, 0> translate <1.2, 0.9, 0>
  pigment { rgbt <1, 1, 1, 0.97> } finish { phong 0.5 } interior { ior 1.6 dispersion 1.08 dispersion_samples 4 } }
sphere { <1.2, 0.9, 0>, 0.3 pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.2 dispersion 1.1 } }
