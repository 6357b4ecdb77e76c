// An #include of a missing file from an include.
#include "nest/missing_inner.inc"
