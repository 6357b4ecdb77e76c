// Float-to-integer conversions are range checked; string functions say what
// is out of range.
#declare A = substr("abc", 2, 5);
#declare B = substr("abc", 0, 1);
#declare C = str(1, 1e10, 2);
#declare D = vstr(3, x, ",", 0, -1e300);
#declare E = seed(1e10);
#declare F = rand(3);
#declare G = chr(0);
#declare H = dimension_size(1, 1);
