// Cross-check of the orthographic camera: the same flat-shaded objects as
// flat_perspective.pov seen through parallel rays. Rendered
// through the whole pipeline by tests/unit/render_golden_test.cpp; POV-Ray's
// reference by scripts/update-goldens.sh as
//  povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Loc = <1.5, 2.2, -6>;
#declare LookAt = <0.2, 0.4, 0>;
#declare D = vnormalize(LookAt - Loc);
#declare R = vnormalize(vcross(<0, 1, 0>, D));
#declare U = vcross(D, R);
camera { orthographic location Loc direction D right 5.2 * R up 3.0 * U }
background { rgb <0.1, 0.2, 0.4> }
#declare Flat = finish { ambient 1 diffuse 0 }
sphere { <0, 0.5, 0>, 0.5 pigment { rgb <1, 0.5, 0.25> } finish { Flat } }
sphere { <1.2, 0.3, 0.8>, 0.3 pigment { rgb <0.2, 0.9, 0.3> } finish { Flat } }
sphere { <-1.3, 0.8, 1.5>, 0.8 pigment { rgb <0.7, 0.7, 0.9> } finish { Flat } }
sphere { <2.6, 1.4, 3>, 0.05 pigment { rgb 1 } finish { Flat } }
plane { y, 0
  pigment { checker rgb <0.9, 0.9, 0.9> rgb <0.05, 0.05, 0.05>
            scale 0.7 rotate y * 30 translate <0.1, 0, 0.2> }
  finish { Flat } }
