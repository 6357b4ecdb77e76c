// chr() of a huge code.
#declare S = chr(1e300);
