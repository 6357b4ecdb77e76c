// Each primitive with its arguments as written (commas optional, as in POV-Ray).
sphere { <1, 2, 3>, 0.5 }
sphere { 0 1 }
box { <-1, -1, -1>, <1, 1, 1> }
box { <1, 2, 3> <0, 0, 0> }
cone { <0, 0, 0>, 1, <0, 2, 0>, 0 }
cone { 0, 1, y, 0.5 open }
cylinder { <0, 0, 0>, <0, 1, 0>, 0.25 }
cylinder { 0, x, 1 open }
disc { <0, 0, 0>, <0, 1, 0>, 2 }
disc { <0, 1, 0>, <0, 0, 2>, 2, 0.5 }
plane { y, -1 }
plane { <0, 2, 0>, 1 }
