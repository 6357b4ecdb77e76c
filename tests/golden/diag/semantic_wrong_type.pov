#declare Name = "ball";
sphere { Name, 1 }
#declare Ball = sphere { 0, 1 }
sphere { 0, Ball }
object { Name }
