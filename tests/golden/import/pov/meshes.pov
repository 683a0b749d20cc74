// Meshes become one rts mesh each: literal flat triangles (a closed tetrahedron, cut in a
// difference: POV-Ray's inside_vector is not needed), smooth triangles (normals per corner), and
// a mesh2 with normal_indices (a corner's vertex and normal named apart).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -5> look_at <0, 0.4, 0> }
light_source { <3, 5, -4> color rgb 1 }
#declare Tetra = mesh {
  triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> }
  triangle { <0, 0, 0>, <1, 0, 0>, <0, 0, 1> }
  triangle { <0, 0, 0>, <0, 0, 1>, <0, 1, 0> }
  triangle { <1, 0, 0>, <0, 1, 0>, <0, 0, 1> }
  inside_vector <0, 0, 1>
}
difference {
  object { Tetra scale 1.6 pigment { color rgb <0.9, 0.3, 0.2> } }
  sphere { <0.1, 0.1, 0.1>, 0.55 pigment { color rgb <0.2, 0.4, 0.9> } }
  rotate <0, 200, 0> translate <-1.3, 0, 0>
}
mesh {
  smooth_triangle { <-0.6, 0, 0>, <-0.7, 0.7, 0>, <0, 1, 0>, <0, 1, -0.2>, <0.6, 0, 0>, <0.7, 0.7, 0> }
  smooth_triangle { <-0.6, 0, 0>, <-0.7, 0.7, 0>, <0.6, 0, 0>, <0.7, 0.7, 0>, <0, -0.2, -0.5>, <0, 0.5, -0.8> }
  pigment { color rgb <0.3, 0.8, 0.3> }
  translate <0, 0.3, 0>
}
mesh2 {
  vertex_vectors { 5, <-0.5, 0, -0.5>, <0.5, 0, -0.5>, <0.5, 0, 0.5>, <-0.5, 0, 0.5>, <0, 0.9, 0> }
  normal_vectors { 4, <0, 0.5, -1>, <1, 0.5, 0>, <0, 0.5, 1>, <-1, 0.5, 0> }
  face_indices { 4, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4> }
  normal_indices { 4, <0, 0, 0>, <1, 1, 1>, <2, 2, 2>, <3, 3, 3> }
  pigment { color rgb <0.9, 0.8, 0.2> }
  rotate <0, 30, 0> translate <1.4, 0, 0>
}
plane { y, 0 pigment { color rgb 1 } }
