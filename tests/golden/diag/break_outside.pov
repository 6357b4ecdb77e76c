// #break stands in a #switch, a #while, a #for or a macro.
#if (1)
  #break
#end
sphere { 0, 1 #break }
