// Cross-check of the patterns with turbulence of their own: marble and wood
// (with and without turbulence, their default maps and a colour map) and
// agate (default and agate_turb), flat-shaded (ambient 1, diffuse 0) on six
// squares. Rendered by tests/unit/render_golden_test.cpp; POV-Ray's
// references by scripts/update-goldens.sh as
//   povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 6.4 * x up 3.6 * y }
background { rgb <0.1, 0.2, 0.4> }
#declare Flat = finish { ambient 1 diffuse 0 }
#macro Tile(X, Y, P)
  box { <-0.95, -0.8, 0>, <0.95, 0.8, 1> pigment { P } finish { Flat } translate <X, Y, 0> }
#end
Tile(-2.1, 0.85, pigment { marble scale 0.5 })
Tile(0, 0.85, pigment { marble turbulence 1.2 color_map { [0 rgb 1] [0.7 rgb <0.4, 0.4, 0.45>] [1 rgb 0.1] } scale 0.6 })
Tile(2.1, 0.85, pigment { wood scale 0.2 translate <2, 0.3, 0> })
Tile(-2.1, -0.85, pigment { wood turbulence <0.1, 0.2, 0> octaves 4 scale 0.3 rotate y * 30 })
Tile(0, -0.85, pigment { agate scale 0.6 })
Tile(2.1, -0.85, pigment { agate agate_turb 0.4 color_map { [0 rgb <0.9, 0.8, 0.7>] [1 rgb <0.3, 0.1, 0.05>] } scale 0.5 })
