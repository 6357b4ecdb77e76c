// Golden render of asos (tests/unit/render_golden_test.cpp): a hexagon and a polygon with a hole (two sub-polygons).
// The reference PNGs beside it are rewritten only by scripts/update-goldens.sh.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.55, 0.7, 0.9> }
camera { location <0, 2.4, -5> look_at <0, 0.7, 0> angle 40 }
light_source { <-4, 7, -5>, color rgb 1 }
plane { y, 0 pigment { color rgb 0.75 } finish { diffuse 0.8 } }
polygon {
  7, <1, 0>, <0.5, 0.866>, <-0.5, 0.866>, <-1, 0>, <-0.5, -0.866>, <0.5, -0.866>, <1, 0>
  scale 0.8 rotate <-20, -15, 0> translate <-0.9, 1.1, 0.5>
  pigment { color rgb <0.1, 0.75, 0.75> }
}
polygon {
  10, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0>, <0.3, 0.3>, <0.7, 0.3>, <0.7, 0.7>, <0.3, 0.7>, <0.3, 0.3>
  scale 1.2 rotate <0, 25, 0> translate <0.4, 0.2, -0.2>
  pigment { color rgb <0.85, 0.2, 0.5> }
  asos { max 5 }
}
