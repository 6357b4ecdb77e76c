// Cross-check of recursive reflection with a low max_trace_level (rays past
// it are black) and coloured reflection. Rendered
// through the whole pipeline by tests/unit/render_golden_test.cpp; POV-Ray's
// reference by scripts/update-goldens.sh as
//  povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 3 }
#declare Loc = <1.5, 2.2, -6>;
#declare LookAt = <0.2, 0.4, 0>;
#declare D = vnormalize(LookAt - Loc);
#declare R = vnormalize(vcross(<0, 1, 0>, D));
#declare U = vcross(D, R);
camera { perspective location Loc direction 1.7 * D right 1.6 * R up 1.0 * U }
background { rgb <0.3, 0.5, 0.8> }
light_source { <-4, 6, -3> color rgb 1 }
sphere { <0, 0.5, 0>, 0.5
  pigment { rgb <0.3, 0.3, 0.35> }
  finish { diffuse 0.3 reflection rgb <0.6, 0.6, 0.5> } }
sphere { <1.2, 0.3, 0.8>, 0.3
  pigment { rgb <0.9, 0.2, 0.1> }
  finish { reflection 0.9 phong 1 } }
sphere { <-1.3, 0.8, 1.5>, 0.8
  pigment { checker rgb <0.8, 0.2, 0.2> rgb <0.9, 0.9, 0.9> scale 0.25 }
  finish { reflection 0.3 } }
plane { y, 0
  pigment { checker rgb 1 rgb 0.1 }
  finish { diffuse 0.5 reflection 0.4 } }
