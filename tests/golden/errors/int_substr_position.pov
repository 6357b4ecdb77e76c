// substr() at a position beyond int.
#declare S = substr("abc", 1e10, 1);
