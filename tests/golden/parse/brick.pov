// pigment brick: POV-Ray's defaults (brick_size <8, 3, 4.5>, mortar 0.5,
// grey mortar and red brick), given colours, brick_size and mortar among the
// transforms in any order (POV-Ray reads them in one loop), a float size,
// declared brick pigments modified and given brick again.
#declare Wall = pigment { brick rgb 0.9, rgb <0.5, 0.1, 0> brick_size <2, 1, 1> mortar 0.1 }
#declare Tiles = pigment { checker rgb 1, rgb 0 }
sphere { 0, 1 pigment { brick } }
sphere { 0, 1 pigment { brick color rgb <1, 1, 1> } }
sphere { 0, 1 pigment { brick rgb 1 rgb 0 } }
sphere { 0, 1 pigment { brick rgb 1, rgb 0 brick_size <1, 0.5, 0.75> mortar 0.05 } }
sphere { 0, 1 pigment { brick rgb 1, rgb 0 scale 0.1 mortar 0.3 rotate x * 90 brick_size 2 } }
sphere { 0, 1 pigment { brick mortar -1 } }  // no mortar at all, as in POV-Ray
sphere { 0, 1 pigment { Wall } }
sphere { 0, 1 pigment { Wall mortar 0.2 scale 2 } }
sphere { 0, 1 pigment { Wall brick rgb 0, rgb 1 } }  // keeps Wall's size and mortar
sphere { 0, 1 pigment { Tiles brick } }                // a new brick: the defaults
sphere { 0, 1 pigment { brick mortar 0.2 } pigment { brick_size 1 } }  // a pigment on a pigment
sphere { 0, 1 texture { pigment { brick rgb 1, rgb 0 } finish { ambient 1 diffuse 0 } scale 3 } }
