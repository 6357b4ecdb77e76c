#include "no_such_file.inc"
sphere { 0, 1 }
