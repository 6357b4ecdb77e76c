// An array within --max-array-elements whose elements would pass --max-memory.
#declare A = array[1500000];
