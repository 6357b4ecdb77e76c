// A scene as many are written: no #version and no assumed_gamma. POV-Ray 3.7
// reads it as a 3.62 scene and turns gamma correction off: colours go to the
// file as they are (a linear 0.5 is code 128, not 188), and the anti-aliasing
// methods compare them as they are. Rendered by
// tests/unit/render_golden_test.cpp; POV-Ray's reference by
// scripts/update-goldens.sh as
//  povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
// (and, for the adaptive and am1 cross-checks, with +A0.3 +AM2 +R3 -J into
// <this>_am2.png and +A0.3 +AM1 +R3 -J into <this>_am1.png)
camera { location <0.5, 1.6, -4.5> look_at <0, 0.5, 0> right x * 1.6 angle 55 }
background { rgb <0.25, 0.35, 0.5> }
light_source { <-4, 6, -3> color rgb <1.0, 0.95, 0.9> }
light_source { <3, 2, -4> color rgb 0.3 }
sphere { <0, 0.6, 0>, 0.6
  pigment { rgb <1, 0.5, 0.2> }
  finish { ambient 0.1 diffuse 0.6 phong 0.8 phong_size 40 } }
box { <0.9, 0, -0.4>, <1.6, 0.7, 0.3>
  pigment { rgb <0.2, 0.4, 0.9> }
  finish { reflection 0.3 } }
plane { y, 0
  pigment { checker rgb <0.9, 0.9, 0.85> rgb <0.15, 0.15, 0.2> scale 0.5 }
  finish { ambient 0.05 diffuse 0.8 } }
