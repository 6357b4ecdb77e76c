camera { location <0, 1, 0> look_at <0, 1, 0> }
camera { location 0 look_at y }
camera { angle 180 }
