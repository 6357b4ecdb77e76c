// A chain of includes, each nesting 190 #if levels: together past the limit, which counts across files.
#include "nest/nest_1.inc"
