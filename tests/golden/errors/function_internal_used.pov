// functions.inc declares internal functions; using one is refused there.
#declare f_noise3d = function { internal(76) }
sphere { 0, 1 pigment { function { f_noise3d(x, y, z) } } }
