// An initialiser longer than the array.
#declare A = array[2] { 1, 2, 3 }
