// An error in a macro's body shows where the macro was called from, and from
// where the file that called it was included.
#declare Missing = 1;
#undef Missing
#include "diag_macros.inc"
