// object { Name … }: a copy of a declared object, modified; for a union, a
// new pigment changes the union's own texture (POV-Ray's rule).
#declare Ball = sphere { 0, 1 pigment { color rgb <1, 0.5, 0> } }
#declare Pair = union { object { Ball translate -x } object { Ball translate x } }
#declare Plain = union { sphere { 0, 1 } pigment { color rgb 1 } }
object { Ball }
object { Ball translate 5*y pigment { scale 2 } }
object { Pair rotate <0, 90, 0> }
object { Plain pigment { color rgb <0, 0, 1> } }
object { sphere { 0, 2 } finish { phong 1 } }
