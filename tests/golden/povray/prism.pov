// Cross-check of prism (linear_sweep) against POV-Ray 3.7: one prism per
// spline kind on a floor, seen from above at an angle:
//   linear_spline     two sub-prisms (a square with a square hole), open at
//                     the front-left, so its inside shows;
//   quadratic_spline  a rounded quadrilateral (its first point a control point);
//   cubic_spline      a Catmull-Rom blob (a control point before and after);
//   bezier_spline     a heart of four segments, with sturm;
// and a linear prism whose heights are written high first (POV-Ray swaps
// them). Rendered by tests/unit/render_golden_test.cpp with one ray per
// pixel; POV-Ray's reference by scripts/update-goldens.sh (povray -A).
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.12, 0.18> }
camera { location <0, 6, -7> look_at <0, 0.3, 0> angle 52 }
light_source { <-4, 9, -6>, color rgb 1 }
light_source { <5, 4, -3>, color rgb 0.3 shadowless }
#declare Matte = finish { ambient 0.12 diffuse 0.8 }
plane { y, 0 pigment { color rgb 0.75 } finish { Matte } }
prism {
  linear_sweep linear_spline 0, 0.8, 10,
  <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>,
  <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>, <-0.5, 0.5>, <-0.5, -0.5>
  open
  pigment { color rgb <0.85, 0.3, 0.25> } finish { Matte phong 0.4 }
  translate <-2.3, 0, 0.9>
}
prism {
  quadratic_spline 0, 1, 6,
  <-1, 0>, <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>
  pigment { color rgb <0.3, 0.75, 0.35> } finish { Matte specular 0.3 }
  translate <0.3, 0, 1.2>
}
prism {
  cubic_spline 0, 0.6, 8,
  <0.4, -0.9>, <1, 0>, <0.2, 1>, <-0.9, 0.6>, <-0.7, -0.6>, <0.4, -0.9>, <1, 0>, <0.2, 1>
  pigment { color rgb <0.3, 0.45, 0.9> } finish { Matte phong 0.5 }
  translate <2.4, 0, 0.6>
}
prism {
  bezier_spline 0, 0.5, 16,
  <0, -1>, <0.5, -0.5>, <1, 0>, <1, 0.5>,
  <1, 0.5>, <1, 1>, <0.3, 1.1>, <0, 0.6>,
  <0, 0.6>, <-0.3, 1.1>, <-1, 1>, <-1, 0.5>,
  <-1, 0.5>, <-1, 0>, <-0.5, -0.5>, <0, -1>
  sturm
  pigment { color rgb <0.9, 0.75, 0.25> } finish { Matte phong 0.6 }
  translate <-0.6, 0, -1.3>
}
prism {
  linear_spline 0.9, 0.1, 4, <0, 0>, <0.8, 0>, <0.4, 0.7>, <0, 0>
  pigment { color rgb <0.7, 0.4, 0.8> } finish { Matte }
  rotate <0, 20, 0> translate <1.4, 0, -1.4>
}
