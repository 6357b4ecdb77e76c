// Cross-check of transparency without an interior (no refraction): a
// bottom layer that filters or transmits shows what is behind the surface,
// filtered by rgb x filter + transmit, and tints the shadows of point
// lights at every surface the shadow ray crosses. Rendered by
// tests/unit/render_golden_test.cpp; POV-Ray's references by
// scripts/update-goldens.sh as
//   povray -D +I<this> +O<this>.png +W160 +H90 -A +FN8
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <-3, 9, -6> rgb 1 }
light_source { <6, 4, -3> rgb <0.3, 0.3, 0.35> }
background { rgb <0.1, 0.15, 0.3> }

plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.85> rgb <0.2, 0.25, 0.3> } }
// A filtering sphere with a highlight: its back surface is seen through its front.
sphere { <-1.6, 1, 0>, 1
    pigment { rgbf <0.3, 0.8, 1, 0.85> }
    finish { ambient 0.05 diffuse 0.2 phong 0.8 phong_size 60 }
}
// A pane that filters and transmits, before an opaque box.
box { <-0.4, 0.01, -1.2>, <1.2, 1.8, -1.1>
    pigment { rgbft <1, 0.4, 0.2, 0.6, 0.2> }
    finish { diffuse 0.4 }
}
box { <0.2, 0, 0.5>, <1.4, 1.2, 1.7> pigment { rgb <0.9, 0.8, 0.3> } rotate y * 20 }
// A transmitting checker on a sphere: half clear, half a transmitting red,
// reflecting a little too.
sphere { <2.4, 0.8, -0.5>, 0.8
    pigment { checker rgbt <1, 1, 1, 1> rgbt <0.9, 0.1, 0.1, 0.4> scale 0.37 }
    finish { reflection 0.2 }
}
// A clear object that casts no shadow.
sphere { <-0.2, 0.35, -2>, 0.35 pigment { rgbf <1, 1, 0.5, 0.9> } no_shadow }
