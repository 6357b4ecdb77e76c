// An orthographic camera without right or up shows what the perspective one
// would at its look_at point (6 units away: 8 x 6 units), as POV-Ray 3.7
// sizes it; with an angle, the view's width at that distance.
#declare Above = camera { orthographic location <0, 6, -0.0001> look_at 0 }
#declare Wide = camera { orthographic location <0, 6, -0.0001> look_at 0 angle 90 }
#declare Far = camera { orthographic location <0, 0, -5> }
camera { Above }
