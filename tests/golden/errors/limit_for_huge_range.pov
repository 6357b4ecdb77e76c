// A #for over a range beyond the loop limit.
#for (I, 0, 1e300)
#end
