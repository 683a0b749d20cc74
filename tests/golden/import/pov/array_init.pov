// Arrays with initial values: a 2-D array of textures (its rows read as lists of lists, each
// texture a material) and a 1-D array of vectors, indexed in nested #for loops.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 1.1, 0> angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, 0 pigment { rgb <0.7, 0.7, 0.7> } }
#declare T = array[2][3] {
  { texture { pigment { rgb <0.9, 0.2, 0.1> } }, texture { pigment { rgb <0.2, 0.8, 0.2> } finish { phong 1 } },
    texture { pigment { checker rgb 0.1 rgb 0.9 scale 0.2 } } },
  { texture { pigment { rgb <0.2, 0.3, 0.9> } }, texture { pigment { rgb <0.9, 0.8, 0.2> } finish { ambient 0.4 } },
    texture { pigment { rgb 1 } } }
}
#declare Column = array[3] { <-1.4, 0, 0>, <0, 0, 0.5>, <1.4, 0, 0> }
#for (Row, 0, 1)
  #for (Col, 0, 2)
    sphere { Column[Col] + <0, 0.55 + Row * 1.1, 0>, 0.5 texture { T[Row][Col] } }
  #end
#end
