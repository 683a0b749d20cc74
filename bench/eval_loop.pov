// Evaluation benchmark (bench/eval.sh): the POV-Ray equivalent of eval_loop.rts.
#declare S = 0;
#declare I = 0;
#while (I < 1000000)
  #declare S = S + sin(I * 0.001) * cos(I * 0.002);
  #declare I = I + 1;
#end
camera { location <0,0,-5> look_at 0 }
