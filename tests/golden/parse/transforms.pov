// translate, rotate, scale (uniform and not), matrix, in order.
sphere { 0, 1 translate <1, 2, 3> }
sphere { 0, 1 rotate <90, 0, 0> }
sphere { 0, 1 rotate y*30 }
sphere { 0, 1 scale 2 }
sphere { 0, 1 scale <1, 2, 3> }
sphere { 0, 1 scale -1 }
sphere { 0, 1 matrix <1, 0, 0,  0.5, 1, 0,  0, 0, 1,  0, 0, 0> }
sphere { 0, 1 translate x rotate z*90 scale 2 }
sphere { 0, 1 scale 2 rotate z*90 translate x }
box { 0, 1 rotate <10, 20, 30> }
