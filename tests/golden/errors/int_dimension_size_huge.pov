// dimension_size() of a dimension beyond int.
#declare A = array[2];
#declare D = dimension_size(A, 1e10);
