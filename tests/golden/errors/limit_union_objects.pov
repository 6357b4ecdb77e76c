// A union whose loop makes more objects than --max-objects.
union {
#for (I, 1, 50001)
  sphere { 0, 1 }
#end
}
