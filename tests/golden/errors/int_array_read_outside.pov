// Reading past an array's end.
#declare A = array[2] { 1, 2 }
#declare X = A[2];
