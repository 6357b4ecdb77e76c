// A name in a function that is neither a parameter nor declared.
#declare F = function(a, b) { a * Scale + b }
