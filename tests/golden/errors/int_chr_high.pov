// chr() past the last Unicode code point.
#declare S = chr(1114112);
