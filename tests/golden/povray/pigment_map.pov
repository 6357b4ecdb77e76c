// Cross-check of pigment_map and average: a gradient blending a plain
// colour, a checker pigment and a declared bozo (its entries' transforms
// relative to the outer pigment's); a nested map (radial's entries a
// marble colour map and a wood pigment map) under turbulence and
// triangle_wave; average of three weighted pigments, one of them with a map
// of its own, and average with its weights left out (1 each), a checker
// of two pigments and a transparent entry over the background; an object transform over a
// declared pigment with a map, and a sine_wave onion with frequency and
// phase. Flat-shaded (ambient 1, diffuse 0) on six squares. Rendered by
// tests/unit/render_golden_test.cpp; POV-Ray's references by
// scripts/update-goldens.sh as
//   povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right 6.4 * x up 3.6 * y }
background { rgb <0.1, 0.2, 0.4> }
#declare Flat = finish { ambient 1 diffuse 0 }
#declare Spots = pigment { bozo color_map { [0 rgb <1, 0.9, 0.2>] [1 rgb <0.6, 0, 0.3>] } scale 0.15 }
#declare Striped = pigment {
  gradient y
  pigment_map {
    [0.2 rgb <0.1, 0.6, 0.3>]
    [0.45 checker rgb 1, rgb <0.2, 0.2, 0.8> scale 0.1]
    [0.7, Spots rotate z * 30]
  }
  scale 1.4 translate -0.7 * y
}
#macro Tile(X, Y, P)
  box { <-0.95, -0.8, 0>, <0.95, 0.8, 1> pigment { P } finish { Flat } translate <X, Y, 0> }
#end
Tile(-2.1, 0.85, pigment { Striped })
Tile(0, 0.85, pigment {
  radial
  pigment_map {
    [0.3 marble color_map { [0 rgb <0.9, 0.9, 0.8>] [1 rgb <0.3, 0.2, 0.1>] } turbulence 0.5 scale 0.3]
    [0.7 wood pigment_map { [0.2 rgb <0.8, 0.5, 0.2>] [0.8 granite color_map { [0 rgb 0] [1 rgb <0.2, 0.9, 1>] } scale 2] }
         scale 0.2]
  }
  frequency 3 triangle_wave turbulence 0.2
})
Tile(2.1, 0.85, pigment {
  average
  pigment_map {
    [1 gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } scale 0.8]
    [2 rgb <0.2, 0.9, 0.2>]
    [0.5 leopard pigment_map { [0 rgb 1] [1 Spots] } scale 0.1]
  }
  translate 0.3 * x
})
Tile(-2.1, -0.85, pigment {
  average
  pigment_map {
    [checker pigment { rgb <1, 0.8, 0.6> } pigment { Spots scale 0.5 } scale 0.25]
    [Spots]
    [1 rgbt <1, 1, 1, 1>]
  }
})
box { <-0.95, -0.8, 0>, <0.95, 0.8, 1>
  pigment { Striped rotate z * 60 }
  finish { Flat }
  scale 0.8 rotate z * -20 translate <0, -0.85, 0> }
Tile(2.1, -0.85, pigment {
  onion
  pigment_map { [0 rgb <0.2, 0.2, 0.5>] [0.5 Spots scale 2] [1 rgb <1, 1, 0.8>] }
  sine_wave frequency 2 phase 0.3 scale 0.6
})
