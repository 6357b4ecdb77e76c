// An array of floats given an object.
#declare A = array[2] { 1, 2 }
#declare A[0] = sphere { 0, 1 }
