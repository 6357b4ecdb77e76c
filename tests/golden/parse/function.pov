// The function pattern in a pigment and a normal, its function written back
// by the dump as one expression (callees in place, captured floats as
// numbers, sum/prod with their own variables).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> look_at 0 }
#declare K = 2.5;
#declare Inner = function(a, b) { a * K - b / 3 }
#declare Outer = function { Inner(x, y) + sum(i, 1, 3, i * z) + min(x, y, -0.5) }
plane { z, 0
  pigment { function { Outer(x, y, z) * prod(j, 1, 2, j) + select(x, 1, 2) } color_map { [0 rgb 0] [1 rgb 1] } frequency 2 }
  normal { function { abs(sin(x * 3)) < 0.5 | y >= 1 } 0.5 }
}
