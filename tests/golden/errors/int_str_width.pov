// str() with a width beyond int.
#declare S = str(1, 3e9, 2);
