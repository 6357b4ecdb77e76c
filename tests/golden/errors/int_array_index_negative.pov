// A negative array index.
#declare A = array[2];
#declare A[-0.5 - 1] = 1;
