// An endless #while: the loop limit stops it.
#declare I = 0;
#while (I < 1)
#end
