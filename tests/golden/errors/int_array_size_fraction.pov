// An array size below 1.
#declare A = array[0.5];
