// A string compared with a float.
#if ("a" = 1)
#end
