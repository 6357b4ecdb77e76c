// camera: angle sets the direction's length from right's; look_at turns the
// camera keeping lengths and handedness (POV-Ray 3.7).
camera {
  location <3, 4, -6>
  look_at <0, 1, 0>
  angle 60
}
