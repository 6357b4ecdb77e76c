// Cross-check of POV-Ray's noise through the map patterns: bozo and spotted
// under each noise_generator, granite, and turbulence moving a gradient (with
// octaves, omega and lambda), flat-shaded (ambient 1, diffuse 0) on six
// squares. Rendered by tests/unit/render_golden_test.cpp; POV-Ray's
// references by scripts/update-goldens.sh as
//   povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 6.4 * x up 3.6 * y }
background { rgb <0.1, 0.2, 0.4> }
#declare Flat = finish { ambient 1 diffuse 0 }
#declare Map = color_map { [0 rgb 0] [0.3 rgb <0.2, 0.2, 0.8>] [0.7 rgb <1, 0.8, 0.3>] [1 rgb 1] }
#macro Tile(X, Y, P)
  box { <-0.95, -0.8, 0>, <0.95, 0.8, 1> pigment { P } finish { Flat } translate <X, Y, 0> }
#end
Tile(-2.1, 0.85, pigment { bozo scale 0.3 })
Tile(0, 0.85, pigment { spotted color_map { Map } noise_generator 1 scale 0.25 translate <-3.3, 0, 0> })
Tile(2.1, 0.85, pigment { bozo color_map { Map } noise_generator 3 scale 0.25 })
Tile(-2.1, -0.85, pigment { granite color_map { Map } scale 1.5 })
Tile(0, -0.85, pigment { gradient x color_map { Map } turbulence 0.6 scale 0.8 })
Tile(2.1, -0.85, pigment { gradient y color_map { Map } turbulence <0.3, 0.8, 0> octaves 3 omega 0.7 lambda 2.5 scale 0.6 })
