// str() with a precision beyond int.
#declare S = str(1, 2, -1e300);
