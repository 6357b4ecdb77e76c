// Cross-check of the brick pattern: a brick floor (the courses laid along z
// by `rotate x*90`, so alternate rows shift by half a brick, on both sides of
// the origin), a wall of POV-Ray's default bricks and colours, and a sphere
// whose mortar 0.3 is not a float (POV-Ray rounds it to one), all flat-shaded
// (ambient 1, diffuse 0). Rendered by tests/unit/render_golden_test.cpp;
// POV-Ray's references by scripts/update-goldens.sh as
//   povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
// (and, for the adaptive and am1 cross-checks, with +A0.3 +AM2 +R3 -J into
// <this>_am2.png and +A0.3 +AM1 +R3 -J into <this>_am1.png)
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Loc = <1.5, 2.2, -6>;
#declare LookAt = <0.2, 0.6, 0>;
#declare D = vnormalize(LookAt - Loc);
#declare R = vnormalize(vcross(<0, 1, 0>, D));
#declare U = vcross(D, R);
camera { perspective location Loc direction 1.5 * D right 1.6 * R up 0.9 * U }
background { rgb <0.1, 0.2, 0.4> }
#declare Flat = finish { ambient 1 diffuse 0 }
plane { y, 0
  pigment { brick rgb <0.85, 0.85, 0.8>, rgb <0.55, 0.2, 0.1>
            brick_size <2, 1, 1> mortar 0.12 rotate x * 90 scale 0.4 rotate y * 20 translate <0.1, 0, 0.05> }
  finish { Flat } }
box { <-3.5, 0, 2.1>, <2.5, 1.6, 2.5> pigment { brick scale 0.1 } finish { Flat } }
sphere { <-1.4, 0.7, 0.2>, 0.7
  pigment { brick rgb 0.9, rgb <0.3, 0.35, 0.6> brick_size 1 mortar 0.3 scale <0.5, 0.4, 0.5> }
  finish { Flat } }
