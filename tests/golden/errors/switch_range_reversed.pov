// #range of a string.
#switch (1)
#range ("a", 2)
  sphere { 0, 1 }
#end
