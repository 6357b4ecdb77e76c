// #switch on a string.
#switch ("a")
#case (1)
  sphere { 0, 1 }
#end
