// A macro that calls itself without end is stopped by the nesting limit, with
// a located error and the ends of the chain of calls.
#macro Forever(N)
  sphere { 0, 1 translate Forever(N + 1) }
#end
Forever(0)
