// union: members flattened in order; the union's transforms move every
// member with the texture it already has; the union's texture goes to the
// members that have none; nested unions pass it down.
union {
  sphere { 0, 1 pigment { color rgb <1, 0, 0> } }
  sphere { x, 1 }
  union {
    box { 0, 1 }
    box { 0, 1 pigment { color rgb <0, 0, 1> } }
    pigment { color rgb <0, 1, 0> }
    translate y
  }
  light_source { <0, 5, 0>, color rgb 1 }
  translate <0, 0, 2>
  pigment { checker color rgb 1, color rgb 0 }
  scale 2
  no_shadow
}
