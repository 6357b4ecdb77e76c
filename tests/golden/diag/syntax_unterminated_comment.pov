/* a comment /* nested */ that never ends
sphere { 0, 1 }
