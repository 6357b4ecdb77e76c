// Cross-check with POV-Ray 3.7 (tests/unit/render_golden_test.cpp): triangles
// and meshes. A triangle and a smooth_triangle, a mesh of flat faces (a
// pyramid), a mesh2 of smooth faces (a coarse sphere, its normals the
// vertices' directions) and a mesh in a difference. References: povray -A.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.55, 0.7, 0.9> }
camera { location <0, 5, -10> look_at <0, 0.8, 1> right x*16/9 angle 50 }
light_source { <-6, 12, -10>, color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.85, color rgb 0.3 } finish { diffuse 0.8 } }
triangle { <-5, 0.1, -1>, <-3, 0.1, -1.5>, <-4, 2.2, 0> pigment { color rgb <0.9, 0.4, 0.2> } }
smooth_triangle { <-2.6, 0.1, -2>, <-1, 0, -1>, <-0.6, 0.1, -2.5>, <1, 0, -1>, <-1.6, 2.0, -1.6>, <0, 1, -1>
  pigment { color rgb <0.3, 0.8, 0.3> } finish { phong 0.7 } }
mesh {
  triangle { <-1, 0, -1>, <1, 0, -1>, <0, 1.5, 0> }
  triangle { <1, 0, -1>, <1, 0, 1>, <0, 1.5, 0> }
  triangle { <1, 0, 1>, <-1, 0, 1>, <0, 1.5, 0> }
  triangle { <-1, 0, 1>, <-1, 0, -1>, <0, 1.5, 0> }
  pigment { color rgb <0.2, 0.5, 0.9> }
  rotate y*20 translate <0.5, 0, 1.5>
}
#declare N = 12;
#declare M = 6;
mesh2 {
  vertex_vectors { (N * (M + 1)),
    #for (j, 0, M) #for (i, 0, N - 1)
      <cos(2 * pi * i / N) * sin(pi * j / M), cos(pi * j / M), sin(2 * pi * i / N) * sin(pi * j / M)>,
    #end #end
  }
  normal_vectors { (N * (M + 1)),
    #for (j, 0, M) #for (i, 0, N - 1)
      <cos(2 * pi * i / N) * sin(pi * j / M), cos(pi * j / M), sin(2 * pi * i / N) * sin(pi * j / M)>,
    #end #end
  }
  face_indices { (2 * N * M),
    #for (j, 0, M - 1) #for (i, 0, N - 1)
      <j * N + i, j * N + mod(i + 1, N), (j + 1) * N + i>,
      <j * N + mod(i + 1, N), (j + 1) * N + mod(i + 1, N), (j + 1) * N + i>,
    #end #end
  }
  pigment { color rgb <0.9, 0.8, 0.3> } finish { phong 0.5 }
  translate <3.3, 1.0, 0.5>
}
difference {
  box { <-0.8, 0, -0.8>, <0.8, 1.2, 0.8> pigment { color rgb <0.85, 0.85, 0.8> } }
  mesh { triangle { <-2, 0.6, -2>, <2, 0.6, -2>, <0, 0.6, 2> } pigment { color rgb <0.9, 0.2, 0.2> } }
  rotate y*30 translate <2.2, 0, -2.6>
}
