// An array size beyond 32 bits.
#declare A = array[1e10];
