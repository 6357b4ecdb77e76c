// A word that is no modifier inside an object.
sphere { 0, 1 shiny }
