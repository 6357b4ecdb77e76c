// Cross-check of the normal patterns against POV-Ray: bumps, dents,
// wrinkles, ripples and waves, and map patterns tilting the normal by their
// slope (granite with turbulence, gradient, agate with accuracy), with bump
// sizes given both ways and transforms, on nine squares lit from the upper
// left with diffuse and phong, and a bumpy sphere. Rendered by
// tests/unit/render_golden_test.cpp; POV-Ray's reference by
// scripts/update-goldens.sh as
//   povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 6.4 * x up 3.6 * y }
background { rgb <0.1, 0.2, 0.4> }
light_source { <-6, 8, -10> rgb 1 }
#declare Lit = finish { ambient 0.15 diffuse 0.75 phong 0.6 phong_size 30 }
#macro Tile(X, Y, N)
  box { <-0.97, -0.55, 0>, <0.97, 0.55, 1> pigment { rgb <0.9, 0.85, 0.7> } normal { N } finish { Lit }
        translate <X, Y, 0> }
#end
Tile(-2.1, 1.2, normal { bumps 0.8 scale 0.15 })
Tile(0, 1.2, normal { dents 3 scale 0.2 })
Tile(2.1, 1.2, normal { wrinkles bump_size 1.2 scale 0.3 rotate <0, 0, 30> })
Tile(-2.1, 0, normal { ripples 0.9 frequency 6 phase 0.3 scale 2 translate <1, 0.5, 0> })
Tile(0, 0, normal { waves 0.7 frequency 3 scale 0.8 })
Tile(2.1, 0, normal { granite, 0.4 turbulence 0.3 scale 1.5 })
Tile(-2.1, -1.2, normal { gradient x 0.8 sine_wave frequency 2 scale 0.5 })
Tile(0, -1.2, normal { agate 0.5 accuracy 0.05 scale 0.4 })
sphere { <2.1, -1.2, 0>, 0.55 pigment { rgb <0.8, 0.6, 0.5> } normal { bumps 0.5 scale 0.08 } finish { Lit } }
