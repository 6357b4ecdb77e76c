// A syntax error inside an included file points into that file.
#include "diag_broken.inc"
sphere { 0, 1 }
