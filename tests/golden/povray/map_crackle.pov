// Cross-check of the crackle pattern: the default form <-1, 1, 0> under
// metric 2, metric 1 with an offset, metric 3 with form <1, 0, 0> (the
// distance to the nearest point), solid cells (the noise at each cell's
// point, under noise_generator 1), turbulence with frequency and a form
// weighing the third point, flat-shaded (ambient 1, diffuse 0) on five
// squares, and as a normal's pattern on the sixth, lit. Rendered by
// tests/unit/render_golden_test.cpp; POV-Ray's references by
// scripts/update-goldens.sh as
//   povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 6.4 * x up 3.6 * y }
background { rgb <0.1, 0.2, 0.4> }
light_source { <-3, 5, -10> rgb 1 }
#declare Flat = finish { ambient 1 diffuse 0 }
#declare Map = color_map { [0 rgb 0] [0.3 rgb <0.2, 0.2, 0.8>] [0.7 rgb <1, 0.8, 0.3>] [1 rgb 1] }
#macro Tile(X, Y, P)
  box { <-0.95, -0.8, 0>, <0.95, 0.8, 1> pigment { P } finish { Flat } translate <X, Y, 0> }
#end
Tile(-2.1, 0.85, pigment { crackle color_map { [0 rgb 0] [1 rgb 1] } scale 0.3 })
Tile(0, 0.85, pigment { crackle metric 1 offset 0.15 color_map { Map } scale 0.35 translate <0.2, 0.1, 0.3> })
Tile(2.1, 0.85, pigment { crackle form <1, 0, 0> metric 3 color_map { Map } scale 0.4 })
Tile(-2.1, -0.85, pigment { crackle solid noise_generator 1 color_map { Map } scale 0.3 translate <-1.7, 0, 0.5> })
Tile(0, -0.85, pigment { crackle form <-0.5, 0.2, 0.5> turbulence 0.3 frequency 2 color_map { Map } scale 0.5 })
box { <-0.95, -0.8, 0>, <0.95, 0.8, 1>
  pigment { rgb <0.9, 0.8, 0.6> }
  normal { crackle 0.8 scale 0.3 }
  finish { ambient 0.2 diffuse 0.8 }
  translate <2.1, -0.85, 0> }
