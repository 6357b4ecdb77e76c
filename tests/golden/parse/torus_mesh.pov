// torus (with sturm), triangle, smooth_triangle, mesh and mesh2: the dump
// writes a mesh face by face, each face as the triangle it is.
torus { 2, 0.5 sturm pigment { rgb <1, 0.5, 0> } rotate x*30 }
triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
smooth_triangle { <0, 0, 0>, <0, 0, -2>, <1, 0, 0>, <1, 0, -1>, <0, 1, 0>, <0, 1, -1> }
mesh {
  triangle { <0, 0, 1>, <1, 0, 1>, <0, 1, 1> }
  smooth_triangle { <0, 0, 2>, z, <1, 0, 2>, z, <0, 1, 2>, y }
  pigment { rgb 0.5 }
  translate x
}
mesh2 {
  vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }
  normal_vectors { 2, z, <0, 1, -1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  normal_indices { 2, <0, 0, 1>, <0, 1, 1> }
  scale 2
}
