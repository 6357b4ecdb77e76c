#declare A = 2 * ;
