// #include: beside this file first, then the -L folders (the tests pass
// tests/golden/include); #local names stay inside the included file.
#include "golden_colors.inc"
#include "golden_shapes.inc"
sphere { 0, 1 pigment { GoldenRed } }
#ifdef (HiddenInside) #error "#local leaked out of the include" #end
