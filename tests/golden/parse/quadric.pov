// quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }, as written (commas optional, but a negative J after a vector needs one: POV-Ray would subtract it).
quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
quadric { <1, 0, 1> <0, 0, 0> <0, 0, 0>, -1 scale 2 }
quadric { <0, 0, 0>, <1, 0, 0>, <0, 0, -1>, 0.5 translate y }
