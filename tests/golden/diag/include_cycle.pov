#include "diag_cycle_a.inc"
