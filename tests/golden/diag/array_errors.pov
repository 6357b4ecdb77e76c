// Misused arrays.
#declare A = array[3];
#declare A[3] = 1;
#declare A[-1] = 1;
sphere { 0, A[0] }
#declare A[0] = 1;
#declare A[1] = <1, 2, 3>;
#declare B = array[0];
#declare C = array[2][2] { {1, 2}, {3} };
#declare D = array[2] { {1, 2}, {3, 4} };
#declare F = 1;
#declare F[0] = 2;
sphere { 0, A[0][0] }
#declare G = array[100000][100000];
#declare E = array[1][1][1][1][1][1];  // a syntax error: the run stops here
