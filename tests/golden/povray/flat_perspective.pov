// Cross-check of the camera mapping, the checker pattern, the background and
// the 8-bit output encoding: flat-shaded objects (ambient 1, diffuse 0) seen
// through a tilted perspective camera whose right/up ratio (1.6) differs from
// the image's (16:9). Rendered by
// tests/unit/render_golden_test.cpp; POV-Ray's reference by
// scripts/update-goldens.sh as
//   povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
// (and, for the adaptive and am1 cross-checks, with +A0.3 +AM2 +R3 -J into
// <this>_am2.png and +A0.3 +AM1 +R3 -J into <this>_am1.png)
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Loc = <1.5, 2.2, -6>;
#declare LookAt = <0.2, 0.4, 0>;
#declare D = vnormalize(LookAt - Loc);
#declare R = vnormalize(vcross(<0, 1, 0>, D));
#declare U = vcross(D, R);
camera { perspective location Loc direction 1.7 * D right 1.6 * R up 1.0 * U }
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
