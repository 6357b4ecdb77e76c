// A function called with the wrong number of arguments.
#declare Blend = function(a, b, t) { a + (b - a) * t }
#declare V = Blend(1, 2);
