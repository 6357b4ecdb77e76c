// An array larger than --max-array-elements.
#declare A = array[3000][1000];
