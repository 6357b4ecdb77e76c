// A mesh2 face that names a vertex past the list.
mesh2 {
  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
  face_indices { 1, <0, 1, 3> }
}
