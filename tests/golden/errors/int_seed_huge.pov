// seed() beyond int.
#declare R = seed(1e10);
