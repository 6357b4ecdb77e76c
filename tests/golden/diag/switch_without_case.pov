// #switch must be followed by #case or #range.
#switch (1)
  #else sphere { 0, 1 }
#end
