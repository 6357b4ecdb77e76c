// 1001 nested #if directives.
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
sphere { 0, 1 }
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
