// A call of a macro that is not declared.
#declare X = Nope(1);
