// texture: pigment and finish together, its own transforms, declared
// textures; object transforms before a texture do not move its pattern,
// those after do.
#declare Tiles = texture {
  pigment { checker color rgb 1, color rgb <0.2, 0.2, 0.3> }
  finish { reflection 0.1 }
  scale 0.5
}
box { 0, 1 texture { Tiles } }
box { 0, 1 translate x texture { Tiles } }
box { 0, 1 texture { Tiles } translate x }
box { 0, 1 texture { Tiles rotate <0, 45, 0> } scale 2 }
sphere { 0, 1 texture { pigment { color rgb <0, 1, 0> } } }
