/* Comments: /* nested */ block comments, // line comments, and numbers in
   every form. */
sphere { <1., .5, 1e-3>, 2.5E+1 }   // trailing comment
sphere { <0, 0, 0> // between arguments
         , 1 /* inside */ }
#declare S = "a \"quoted\" string\twith escapes\n";
#debug S
