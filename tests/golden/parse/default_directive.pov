// #default: what later textures, pigments and finishes start from, and the
// texture of an object without one (taken when the object is placed).
sphere { 0, 1 }                                    // POV-Ray's default texture
#default { finish { ambient 0.2 phong 0.5 } }
#declare Later = sphere { 0, 2 }
#default { pigment { rgb <1, 0, 0> } }
object { Later }                                   // red, with the finish above
box { 0, 1 pigment { checker } }                   // the default finish, checker
#default { texture { pigment { rgb 1 } finish { diffuse 0.9 } } }
cylinder { 0, y, 1 }
default { finish { specular 0.3 } }                // POV-Ray's old spelling, without '#'
cone { 0, 1, y, 0 }
