camera { orthographic location <0, 0, -5> look_at 0 angle 30 }
