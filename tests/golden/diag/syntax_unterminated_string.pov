#declare Name = "no end
sphere { 0, 1 }
