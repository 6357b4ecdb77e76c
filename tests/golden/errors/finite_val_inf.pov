// val() of "inf".
#declare X = val("-inf");
