// assumed_gamma other than 1: POV-Ray decodes the working value
// (v^assumed_gamma) before encoding the file, and its anti-aliasing compares
// samples after decoding it. Rendered by tests/unit/render_golden_test.cpp;
// POV-Ray's reference by scripts/update-goldens.sh as
//  povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
// (and, for the adaptive and am1 cross-checks, with +A0.3 +AM2 +R3 -J into
// <this>_am2.png and +A0.3 +AM1 +R3 -J into <this>_am1.png)
#version 3.7;
global_settings { assumed_gamma 2.2 }
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
