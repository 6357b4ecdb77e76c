// Cross-check of the map patterns without noise: gradient (with a colour
// map, frequency, phase and each wave), radial, onion and leopard (their
// default maps), and POV-Ray's older colour map entries, flat-shaded
// (ambient 1, diffuse 0) on six squares. Rendered by
// tests/unit/render_golden_test.cpp; POV-Ray's references by
// scripts/update-goldens.sh as
//   povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 6.4 * x up 3.6 * y }
background { rgb <0.1, 0.2, 0.4> }
#declare Flat = finish { ambient 1 diffuse 0 }
#declare Map = color_map { [0 rgb <1, 0.9, 0.2>] [0.5 rgb <0.8, 0.1, 0.1>] [0.5 rgb <0.1, 0.3, 0.8>] [1 rgb 1] }
#macro Tile(X, Y, P)
  box { <-0.95, -0.8, 0>, <0.95, 0.8, 1> pigment { P } finish { Flat } translate <X, Y, 0> }
#end
Tile(-2.1, 0.85, pigment { gradient x color_map { Map } scale 0.7 translate 0.1 })
Tile(0, 0.85, pigment { gradient <1, 1, 0> color_map { Map } frequency 2 phase 0.3 triangle_wave })
Tile(2.1, 0.85, pigment { gradient y color_map { [0, 0.6 color rgb 0 color rgb <0, 1, 0>] [0.6, 1 color rgb <1, 0, 1> color rgb 1] } sine_wave scale 0.5 })
Tile(-2.1, -0.85, pigment { radial frequency 3 rotate x * 90 })
Tile(0, -0.85, pigment { onion color_map { Map } scale 0.4 translate <0.2, 0.1, 0> })
Tile(2.1, -0.85, pigment { leopard scale 0.08 })
