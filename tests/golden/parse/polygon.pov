// polygon: POV-Ray's vertex list; 2-D points get z = 0; a sub-polygon closes
// when its first point repeats, and the last may be left open.
polygon { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
polygon {
  10,
  <0, 0>, <3, 0>, <3, 3>, <0, 3>, <0, 0>,   // outer square, closed
  <1, 1>, <2, 1>, <2, 2>, <1, 2>, <1, 1>    // a square hole
}
polygon { 3, <0, 0, 1>, <1, 0, 1>, <0, 1, 1> rotate x*90 }
