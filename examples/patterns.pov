// The map patterns in a lit scene: a marble floor, a granite sphere and a
// gradient sphere, measured against a converged POV-Ray render in
// docs/results.md ("Map patterns"). POV-Ray 3.7 renders it too.
//   asos render examples/patterns.pov -o patterns.png
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -6> look_at <0, 0.7, 0> angle 50 }
light_source { <-4, 8, -6>, rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0
  pigment { marble turbulence 0.9 color_map { [0 rgb 0.95] [0.8 rgb <0.6, 0.55, 0.5>] [1 rgb 0.15] } scale 0.8 } }
sphere { <-1.3, 1, 0.5>, 1
  pigment { granite color_map { [0 rgb <0.9, 0.75, 0.7>] [0.4 rgb <0.6, 0.4, 0.4>] [1 rgb 0.1] } scale 0.8 }
  finish { phong 0.4 } }
sphere { <1.3, 1, 0.5>, 1
  pigment { gradient y color_map { [0 rgb <0.1, 0.2, 0.8>] [0.5 rgb <0.9, 0.9, 0.2>] [1 rgb <0.1, 0.2, 0.8>] }
            turbulence 0.3 scale 0.5 }
  finish { phong 0.4 } }
