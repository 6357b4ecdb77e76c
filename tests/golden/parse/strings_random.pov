// String functions, POV-Ray's random numbers and the clock's values when not
// animating; the values checked against POV-Ray 3.7 with #debug.
#declare S = seed(123);
sphere { <rand(S), rand(S), rand(seed(-5))>, 1 }   // 0.904772982212, 0.995137868914, 0.890052870123
#declare Name = concat("Ab", chr(67), str(1.5, -6, 2), vstr(3, <1, 2, 3>, ",", 0, 1));
#debug concat(Name, "\n")                          // AbC001.501.0,2.0,3.0
box { <strlen(Name), strcmp("abc", "abd"), asc(substr(Name, 2, 1))>,
      <val("2.5"), strlen(strupr("xy")), strcmp(strlwr("Q"), "q")> }
cylinder { <frame_number, initial_frame, final_frame>, <initial_clock, final_clock + 1, clock_on>, 1 + clock_delta }
