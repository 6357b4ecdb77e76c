// Cross-check of layered textures (texture { A } texture { B }: B over A):
// each layer lit with its own finish, the layers under one seen through its
// filter and transmit, their reflections traced with what is left of the
// ray's weight. Rendered by tests/unit/render_golden_test.cpp; POV-Ray's
// references by scripts/update-goldens.sh as
//   povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -7> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 8, -6> rgb 1 }
light_source { <5, 3, -4> rgb <0.4, 0.45, 0.5> }
background { rgb <0.1, 0.15, 0.3> }

// A declared layered texture: a wood under a grain that filters and transmits.
#declare T_Grain =
    texture { pigment { wood color_map { [0 rgb <0.8, 0.5, 0.2>] [1 rgb <0.5, 0.25, 0.1>] } turbulence 0.1 scale 0.3 }
              finish { diffuse 0.7 } }
    texture { pigment { gradient x color_map { [0 rgbf <0.3, 0.1, 0.0, 0.6>] [0.5 rgbt <1, 1, 1, 1>]
                                               [1 rgbft <0.2, 0.1, 0.05, 0.3, 0.4>] } scale 0.25 }
              finish { phong 0.6 phong_size 30 } }

plane { y, 0
    texture { pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.3, 0.35, 0.4> } }
    texture { pigment { bozo color_map { [0 rgbt <0.2, 0.6, 0.2, 0.3>] [1 rgbf <1, 1, 1, 1>] } scale 0.6 }
              finish { ambient 0.05 diffuse 0.5 reflection 0.3 } }
}
// A sphere: a red bottom, a transparent checker of a blue half-filter over it
// with highlights of its own.
sphere { <-1.8, 1, 0>, 1
    texture { pigment { rgb <0.8, 0.1, 0.1> } finish { diffuse 0.8 } }
    texture { pigment { checker rgbf <0.1, 0.3, 1, 0.5> rgbt <1, 1, 1, 1> scale 0.4 }
              finish { specular 0.8 roughness 0.02 } }
}
// The declared texture, moved and scaled as one.
box { <-0.7, 0, -0.7>, <0.7, 1.4, 0.7> texture { T_Grain scale 1.5 rotate y * 20 } rotate y * 30 }
// A pigment first, then a texture over it; then a third layer.
sphere { <1.9, 0.9, 0.3>, 0.9
    pigment { granite color_map { [0 rgb <0.2, 0.5, 0.2>] [1 rgb <0.9, 0.9, 0.7>] } scale 2 }
    texture { pigment { onion color_map { [0 rgbt <0.1, 0.1, 0.6, 0.5>] [1 rgbt 1] } scale 0.3 } }
    texture { pigment { rgbf <1, 0.8, 0.6, 0.9> } finish { ambient 0 diffuse 0.2 phong 1 } }
}
