// clipped_by and bounded_by as asos places them: a clip is the object's
// intersection with its clip objects (their leaves make no objects); a bound
// POV-Ray keeps clips likewise; a bound POV-Ray removes is gone.
sphere { 0, 1 clipped_by { box { -0.5, 0.5 } } pigment { rgb 1 } }
sphere { 0, 1 clipped_by { plane { y, 0 } plane { x, 0.2 inverse } } translate x }
difference { box { -1, 1 } sphere { 0, 1.2 } clipped_by { sphere { 0, 1.3 } rotate y * 10 } scale 2 }
union { sphere { 0, 1 } sphere { x, 1 } bounded_by { box { <-1, -1, -1>, <2, 1, 1> } } clipped_by { bounded_by } }
sphere { 0, 1 bounded_by { box { -2, 2 } } }
