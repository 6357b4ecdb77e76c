// Benchmark scene "coverage" (docs/performance.md, "EPS as a promise"): a
// flat scene whose image is known exactly (asos/testing/exact_coverage.hpp):
// convex polygons and discs, each one colour lit by ambient only, none
// crossing another's plane and no two discs in one pixel. Sizes in pixels at
// 320 x 240 (one pixel is 0.1 unit on the plane z = 0):
//   * a fan of 16 sliver triangles 0.2 to 0.7 pixel wide at their tips, each
//     on a plane of its own (z = 0.1 i), so that they overlap at the centre
//     in one depth order;
//   * a star of 8 triangles edge to edge, several edges through one pixel;
//   * a row of discs 0.5 to 2.5 pixels across and a row of tilted ones;
//   * two large slanted quadrilaterals behind the rest, one behind the other.
//   asos render examples/bench/coverage.pov -W 320 -H 240 -o coverage.png
//   asos-bench eps -o build/eps
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.05, 0.07, 0.1> }
camera { location <0, 0, -20> look_at <0, 0, 0> angle 77.3196 }
#declare Flat = finish { ambient 1 diffuse 0 }

#for (I, 0, 15)
  #declare A = radians(-80 + 160 * I / 15);
  #declare W = (0.02 + 0.05 * I / 15) / 2;
  #declare Tip = <-6, 3> + 7 * <sin(A), cos(A)>;
  #declare Side = W * <cos(A), -sin(A)>;
  polygon { 4, <-6, 3>, Tip + Side, Tip - Side, <-6, 3>
    translate 0.1 * I * z pigment { color rgb <0.9, 0.85 - 0.04 * I, 0.3 + 0.04 * I> } finish { Flat } }
#end

#for (I, 0, 7)
  #declare A0 = radians(45 * I + 10);
  #declare A1 = radians(45 * I + 55);
  polygon { 4, <9, 4>, <9, 4> + 3 * <cos(A0), sin(A0)>, <9, 4> + 3 * <cos(A1), sin(A1)>, <9, 4>
    pigment { color rgb <0.2 + 0.1 * I, 0.9 - 0.1 * I, 0.5> } finish { Flat } }
#end

#for (I, 0, 9)
  #declare R = 0.025 + 0.1 * I / 9;
  disc { <-11 + 2.4 * I, -4, 0>, -z, R pigment { color rgb <0.3, 0.8, 0.95> } finish { Flat } }
  disc { <-11 + 2.4 * I, -7, 0>, <sin(radians(20 * I)), 0.3, -1>, 2 * R pigment { color rgb <0.95, 0.5, 0.7> } finish { Flat } }
#end

polygon { 5, <2, -2>, <7, -3>, <8, 1>, <3, 0.5>, <2, -2> rotate y * 30 translate 6 * z pigment { color rgb <0.6, 0.6, 0.2> } finish { Flat } }
polygon { 4, <-2, -10>, <4, -6>, <0, -2>, <-2, -10> rotate x * -20 translate 8 * z pigment { color rgb <0.4, 0.2, 0.8> } finish { Flat } }
