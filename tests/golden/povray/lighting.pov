// Cross-check of the lighting model: diffuse, brilliance, phong, specular,
// ambient_light, light fade, a shadowless coloured light and point-light
// shadows. Rendered by tests/unit/render_golden_test.cpp;
// POV-Ray's reference by scripts/update-goldens.sh as
//  povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
// (and, for the adaptive and am1 cross-checks, with +A0.3 +AM2 +R3 -J into
// <this>_am2.png and +A0.3 +AM1 +R3 -J into <this>_am1.png)
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <0.8, 0.9, 1.0> }
#declare Loc = <1.5, 2.2, -6>;
#declare LookAt = <0.2, 0.4, 0>;
#declare D = vnormalize(LookAt - Loc);
#declare R = vnormalize(vcross(<0, 1, 0>, D));
#declare U = vcross(D, R);
camera { perspective location Loc direction 1.7 * D right 1.6 * R up 1.0 * U }
background { rgb <0.02, 0.02, 0.05> }
light_source { <-4, 6, -3> color rgb <1.0, 0.95, 0.9> fade_distance 6 fade_power 2 }
light_source { <3, 2, -4> color rgb <0.2, 0.25, 0.4> shadowless }
sphere { <0, 0.5, 0>, 0.5
  pigment { rgb <1, 0.5, 0.25> }
  finish { ambient 0.1 diffuse 0.7 phong 0.8 phong_size 30 } }
sphere { <1.2, 0.3, 0.8>, 0.3
  pigment { rgb <0.2, 0.9, 0.3> }
  finish { ambient 0.2 diffuse 0.5 brilliance 3 specular 0.6 roughness 0.02 } }
sphere { <-1.3, 0.8, 1.5>, 0.8
  pigment { checker rgb <0.8, 0.2, 0.2> rgb <0.9, 0.9, 0.9> scale 0.25 }
  finish { diffuse 0.6 specular 0.3 phong 0.3 } }
plane { y, 0
  pigment { rgb <0.7, 0.7, 0.6> }
  finish { ambient 0.05 diffuse 0.8 } }
