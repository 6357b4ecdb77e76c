// substr() with a length beyond int.
#declare S = substr("abc", 1, -3e9);
