// Cross-check with POV-Ray 3.7 (tests/unit/render_golden_test.cpp): poly,
// quartic, cubic. A torus written as a quartic (tilted), shapesq.inc's
// Torus_40_12 with sturm under a non-uniform scale, its Piriform (whose top
// terms vanish across x: unbounded to asos, as to POV-Ray) and an ellipsoid
// as poly 2. References: povray -A.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.55, 0.7, 0.9> }
camera { location <0, 5, -10> look_at <0, 0.8, 1> right x*16/9 angle 50 }
light_source { <-6, 12, -10>, color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.85, color rgb 0.3 } finish { diffuse 0.8 } }
// (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2), R = 1, r = 0.35
#declare K = 1 - 0.35 * 0.35;
quartic {
  <1, 0, 0, 0, 2, 0, 0, 2, 0, 2*K - 4,
   0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
   1, 0, 0, 2, 0, 2*K, 0, 0, 0, 0,
   1, 0, 2*K - 4, 0, K*K>
  pigment { color rgb <0.9, 0.4, 0.2> } finish { phong 0.6 }
  rotate <-20, 0, 15> translate <-3.6, 0.9, 0>
}
// shapesq.inc's Torus_40_12
quartic {
  < 1,   0,   0,    0,     2,   0,   0,   2,   0, -104,
    0,   0,   0,    0,     0,   0,   0,   0,   0,    0,
    1,   0,   0,    2,     0,  56,   0,   0,   0,    0,
    1,   0, -104,   0,   784>
  sturm
  scale <0.12, 0.18, 0.12> rotate <60, 20, 0> translate <3.4, 1.4, 0.5>
  pigment { color rgb <0.3, 0.8, 0.3> }
}
// shapesq.inc's Piriform: (x^4 - x^3) + y^2 + z^2 = 0
quartic {
  < 4,   0,   0,   -4,  0,   0,   0,   0,   0,  0,
    0,   0,   0,    0,  0,   0,   0,   0,   0,  0,
    0,   0,   0,    0,  0,   1,   0,   0,   0,  0,
    0,   0,   1,    0,  0>
  rotate z*90 scale 1.6 translate <1.2, 0, -2.5>
  pigment { color rgb <0.9, 0.8, 0.3> }
}
// x^2 + 2 y^2 + z^2 - 1
poly { 2, <1, 0, 0, 0, 2, 0, 0, 1, 0, -1> translate <-0.4, 0.75, 0.8> pigment { color rgb <0.2, 0.6, 0.9> } }
