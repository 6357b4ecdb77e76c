// A string doubled in a loop: refused at --max-string-length before it is allocated.
#declare S = "abcdefgh";
#for (I, 1, 40)
  #declare S = concat(S, S);
#end
