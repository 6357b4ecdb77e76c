// Benchmark scene "edges" (docs/performance.md): long sharp edges at many
// angles, where every method's error is coverage error. Sizes in pixels are at
// 320 x 240 (one pixel is 0.1 unit on the plane z = 0):
//   * a fan of 24 long triangles, each a sliver 0.2 to 0.7 pixel wide at its
//     tip, spread over half a turn so that edges cross pixels at every angle;
//   * twelve rotated boxes whose silhouettes are long straight edges;
//   * a row of discs 0.5 to 2.5 pixels across facing the camera, and a row
//     of tilted ones;
//   * polygons edge to edge (a star of 8 triangles sharing the centre), where
//     a pixel is crossed by several edges at once.
// One point light at the eye, so that shading varies little across a face.
//   asos render examples/bench/edges.pov -W 320 -H 240 -o edges.png
//   asos-bench accuracy examples/bench/edges.pov -o build/accuracy
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.08, 0.1, 0.14> }
camera { location <0, 0, -20> look_at <0, 0, 0> angle 77.3196 }
light_source { <0, 0, -20>, color rgb 1 }
#declare Flat = finish { ambient 0.3 diffuse 0.7 }

// The fan: triangles from a common apex, each ending in a sliver.
#for (I, 0, 23)
  #declare A = radians(7.5 * I + 2);
  #declare W = 0.01 + 0.025 * mod(I * 0.618034, 1);
  polygon { 4, <-6, -1>, <-6 + 8 * cos(A) - W * sin(A), -1 + 8 * sin(A) + W * cos(A)>,
    <-6 + 8 * cos(A) + W * sin(A), -1 + 8 * sin(A) - W * cos(A)>, <-6, -1>
    pigment { color rgb <0.9, 0.85 - 0.02 * I, 0.3 + 0.025 * I> } finish { Flat } }
#end

// Boxes at many angles.
#for (I, 0, 11)
  box { <-0.9, -0.25, -0.25>, <0.9, 0.25, 0.25>
    rotate <10 + 7 * I, 20 + 11 * I, 13 * I> translate <4 + 2.6 * mod(I, 4), 9 - 2.6 * floor(I / 4), 0>
    pigment { color rgb <0.3 + 0.05 * I, 0.7, 0.95 - 0.05 * I> } finish { Flat } }
#end

// Discs 0.5 to 2.5 pixels across, facing the camera, then tilted.
#for (I, 0, 15)
  #declare R = 0.025 + 0.1 * I / 15;
  disc { <-14 + 1.2 * I, -7, 0>, -z, R pigment { color rgb <1, 0.55, 0.25> } finish { Flat } }
  disc { <-14 + 1.2 * I + 0.33, -9, 0>, <sin(0.4 * I), 0.3, -1>, R * 1.6 pigment { color rgb <0.35, 1, 0.45> } finish { Flat } }
#end

// A star of triangles sharing the centre: several edges per pixel near it.
#for (I, 0, 7)
  #declare A = radians(45 * I + 5);
  #declare B = radians(45 * I + 50);
  polygon { 4, <9, -4>, <9 + 4 * cos(A), -4 + 4 * sin(A)>, <9 + 4 * cos(B), -4 + 4 * sin(B)>, <9, -4>
    pigment { color rgb <0.2 + 0.1 * I, 0.25, 0.8 - 0.08 * I> } finish { Flat } }
#end
// A plane behind, so that the edges of the fan and the star lie against a surface too.
plane { z, 3 pigment { color rgb <0.35, 0.33, 0.3> } finish { Flat } }
