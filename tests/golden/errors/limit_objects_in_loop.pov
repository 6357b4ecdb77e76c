// More objects placed by a loop than --max-objects.
#for (I, 1, 50001)
  sphere { 0, 1 }
#end
