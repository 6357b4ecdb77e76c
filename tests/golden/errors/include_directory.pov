// An #include of a folder.
#include "nest"
