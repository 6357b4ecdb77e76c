sphere { 0, 1 }
#end
