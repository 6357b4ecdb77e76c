// sky_sphere layers in a scene older than 3.7 (no #version: read as 3.62),
// whose sky POV-Ray 3.7 composes with 3.6's arithmetic: a filtering layer
// over a gradient, over a background; constant fog with a filter and a transmit.
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -5> look_at <0, 1.5, 0> angle 70 }
light_source { <5, 10, -10>, rgb 1 }
background { rgb <0.3, 0.2, 0.1> }
sky_sphere {
  pigment { gradient y color_map { [0 rgbt <1, 0.9, 0.7, 0.5>] [1 rgbt <0.2, 0.3, 0.9, 0.2>] } }
  pigment { gradient x color_map { [0 rgbf <1, 0.5, 0.5, 0.6>] [1 rgbft <0.5, 1, 0.5, 0.2, 0.3>] } scale 2 translate -x }
}
fog { distance 30 color rgbft <0.7, 0.8, 0.9, 0.5, 0.5> }
sphere { <0, 1, 0>, 1 pigment { rgb <1, 0.3, 0.2> } finish { reflection 0.4 } }
