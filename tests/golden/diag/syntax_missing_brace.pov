// A block without its closing brace.
sphere { <0, 1, 0>, 1
  pigment { color rgb 1 }
