// A number literal beyond a double.
#declare X = 1e400;
