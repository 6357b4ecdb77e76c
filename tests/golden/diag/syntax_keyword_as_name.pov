// A keyword cannot be declared.
#declare sphere = 1;
