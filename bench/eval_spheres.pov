// Evaluation benchmark (bench/eval.sh): the POV-Ray equivalent of eval_spheres.rts.
#declare I = 0;
#while (I < 300)
  #declare J = 0;
  #while (J < 300)
    sphere { <I * 0.5, 0, J * 0.5>, 0.2
      texture { pigment { color rgb <I / 300, 0.5, J / 300> } finish { diffuse 0.7 specular 0.3 reflection 0.2 } } }
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
camera { location <0,5,-5> look_at 0 }
