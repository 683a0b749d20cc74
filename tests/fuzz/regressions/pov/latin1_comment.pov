// fuzz_pov: a Latin-1 comment (café, °C) and string were written into the translation as
// bytes that are not UTF-8, which rts refuses; they are now read as Latin-1.
#declare Name = "naïve";
sphere { 0, 1 } // résumé
