// chr(0).
#declare S = chr(0);
