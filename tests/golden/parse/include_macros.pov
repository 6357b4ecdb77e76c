// Macros from an include file, called here (the include folder is searched as
// for include.pov).
#include "golden_macros.inc"
GoldenPost(1, GoldenHalf(6))
union { GoldenPost(2, 1) GoldenPost(3, 2) }
