// Cross-check of the function pattern (pigment { function { … } }): user
// functions of x, y, z with named parameters, functions calling functions,
// a captured float, sum/prod, select, comparisons and logic, values above 1
// (wrapped) and below 0 (wrapped by the wave), with frequency and a wave,
// and as a normal's pattern; flat-shaded (ambient 1, diffuse 0) on six
// squares, the last lit. Rendered by tests/unit/render_golden_test.cpp;
// POV-Ray's references by scripts/update-goldens.sh as
//   povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 6.4 * x up 3.6 * y }
background { rgb <0.1, 0.2, 0.4> }
light_source { <-3, 5, -10> rgb 1 }
#declare Flat = finish { ambient 1 diffuse 0 }
#declare Map = color_map { [0 rgb <1, 0.9, 0.2>] [0.5 rgb <0.8, 0.1, 0.1>] [0.5 rgb <0.1, 0.3, 0.8>] [1 rgb 1] }
#declare K = 0.35;
#declare Rings = function(a, b) { sqrt(a*a + b*b) * K * 3 }
#declare Twist = function { Rings(x, y) + sin(atan2(y, x) * 3) * 0.1 }
#declare Steps = function(n) { sum(i, 1, 4, (n > i * 0.3) * 0.25) }
#declare Waves = function(a) { prod(j, 1, 2, cos(a * j)) }
#macro Tile(X, Y, P)
  box { <-0.95, -0.8, 0>, <0.95, 0.8, 1> pigment { P } finish { Flat } translate <X, Y, 0> }
#end
Tile(-2.1, 0.85, pigment { function { Twist(x, y, z) } color_map { Map } translate <-2.1, 0.85, 0> })
Tile(0, 0.85, pigment { function { x * 1.37 + y * 1.01 + 0.0123 } color_map { Map } })
Tile(2.1, 0.85, pigment { function { Steps(x + 1.1) * 0.9 + select(y, 0, 0.1) } color_map { Map } translate <2.1, 0, 0> })
Tile(-2.1, -0.85, pigment { function { Waves(x * 4) * 0.5 + 0.5 } color_map { Map } })
Tile(0, -0.85, pigment { function { (abs(x) < 0.3 & y > -0.5) * (y + 0.5) + (abs(x) >= 0.3) * -y } frequency 2 triangle_wave color_map { Map } translate <0, -0.85, 0> })
box { <-0.95, -0.8, 0>, <0.95, 0.8, 1>
  pigment { rgb <0.9, 0.8, 0.6> }
  normal { function { sin(x * 6) * cos(y * 6) * 0.5 + 0.5 } 0.8 }
  finish { ambient 0.2 diffuse 0.8 }
  translate <2.1, -0.85, 0> }
