// A fog of nothing rts reads (only unknown words): fuzz_pov found the import indexing its empty settings.
fog { edistance 1 pigment { rgb <0.2, 0.6, 0.9> } }
sphere { <2, 1, 20>, 1 }
