// An #include of a device, not a file.
#include "/dev/zero"
