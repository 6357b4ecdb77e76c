// poly, quartic and cubic: POV-Ray's coefficient order, sturm kept, the
// commas optional.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -8> look_at 0 }
light_source { <5, 10, -5>, rgb 1 }
// The torus of major radius sqrt(40), minor sqrt(12) (shapesq.inc's Torus_40_12).
quartic {
  < 1,   0,   0,    0,     2,   0,   0,   2,   0, -104,
    0,   0,   0,    0,     0,   0,   0,   0,   0,    0,
    1,   0,   0,    2,     0,  56,   0,   0,   0,    0,
    1,   0, -104,   0,   784>
  sturm
  scale 0.15
  pigment { rgb <1, 0.5, 0.2> }
}
// A unit sphere as poly 2, translated.
poly { 2 <1 0 0 0 1 0 0 1 0, -1> translate x * 2 pigment { rgb 0.8 } }
// z = x^3 - y^3 (shapesq.inc's Cubic_Saddle_1 without its clip).
cubic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0, 0, 0, 0, 0, -1, 0> translate -x * 3 }
