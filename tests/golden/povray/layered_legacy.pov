// Layered textures in a scene older than 3.7: POV-Ray takes a layer's own
// share of its light as 1 - (filter x its colour's largest component +
// transmit) there. Rendered as layered.pov is.
#version 3.6;
camera { location <0, 1.5, -5> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.1, 0.15, 0.3> }
plane { y, 0
    texture { pigment { rgb <0.3, 0.5, 0.3> } }
    texture { pigment { checker rgbf <1, 0.2, 0.2, 0.6> rgbt <0.1, 0.1, 0.8, 0.5> } finish { phong 0.5 } }
}
sphere { <0, 1, 0>, 1
    texture { pigment { rgb <0.9, 0.8, 0.2> } finish { phong 0.4 } }
    texture { pigment { gradient y color_map { [0 rgbf <0.2, 0.9, 0.4, 0.8>] [1 rgbft <0.6, 0.1, 0.9, 0.3, 0.5>] } scale 0.5 } }
}
