// A background colour that overflows.
background { rgb exp(800) }
