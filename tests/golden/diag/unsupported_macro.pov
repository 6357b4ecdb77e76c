// Macros are not part of the asos language.
#macro Thing(R)
  sphere { 0, R }
#end
