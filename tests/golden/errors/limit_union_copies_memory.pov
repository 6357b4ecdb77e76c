// Copies of a declared union, after many objects: refused by --max-memory before the copy is made.
#for (I, 1, 40000)
  sphere { 0, 1 }
#end
#declare A = union { #for (I, 1, 1000) sphere { 0, 1 } #end }
#declare B = union {
#for (I, 1, 40)
  object { A translate I*x }
#end
}
