// #switch with #case, #range, #else and #break; as in POV-Ray a clause that
// matches runs on into the next ones until a #break. #break also leaves
// #while and #for.
#macro Pick(V)
  #switch (V)
    #case (1)
      sphere { <V, 0, 0>, 0.1 }
    #case (2)
      sphere { <V, 1, 0>, 0.2 }               // 1 and 2 both get here
    #break
    #range (3, 4.5)
      box { <V, 0, 0>, <V + 1, 1, 1> }
    #break
    #else
      cylinder { <V, 0, 0>, <V, 1, 0>, 0.3 }  // neither 1, 2 nor 3 to 4.5
  #end
#end
Pick(1) Pick(2) Pick(4) Pick(7)
#declare I = 0;
#while (1)
  #if (I = 3) #break #end
  disc { <0, I, 0>, y, 1 }
  #declare I = I + 1;
#end
#for (J, 0, 10)
  #if (J > 1) #break #end
  plane { y, J }
#end
