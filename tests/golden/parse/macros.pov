// #macro: a body read where the macro is called (at the top, among an object's
// modifiers, in a union, a pigment, a texture, a finish, for a value), #local
// names per call, recursion, a bare identifier passed by reference.
#macro Ball(Centre, Radius)
  sphere { Centre, Radius }
#end
#macro Twice(V) (2 * V) #end                // a value
#macro Grey(L)
  #local C = rgb L;                          // local to the call
  C
#end
#macro Lift(H) translate H * y #end          // object modifiers
#macro Shiny() phong 0.8 phong_size 60 #end  // finish items
#macro Paint(C) pigment { C } #end           // a texture's item
#macro Row(N)                                // recursion
  #if (N > 0)
    Ball(<N, 0, 0>, 0.25)
    Row(N - 1)
  #end
#end
#macro Bump(Counter) #declare Counter = Counter + 1; #end
#macro Thing(S)                              // an object as a value
  #local Size = S * 0.5;
  box { -Size, Size }
#end

Ball(<0, 1, 0>, Twice(0.5))
sphere { 0, 1 Lift(3) pigment { Grey(0.5) } finish { Shiny() } }
box { 0, 1 texture { Paint(rgb <1, 0, 0>) } }
union { Row(3) Lift(-1) }
#declare Count = 0;
Bump(Count) Bump(Count)
cylinder { 0, y, Count }                     // radius 2
#declare Block = Thing(4);
object { Block translate x * 10 }
object { Thing(1) }
#ifdef (C) #error "a macro's #local leaked out" #end
#ifdef (Size) #error "a macro's #local leaked out" #end
