// A right-handed setup (right = -x, as in scenes converted from other
// programs) keeps its handedness through look_at.
camera {
  location <0, 2, 5>
  up y
  right -x * 4 / 3
  look_at <0, 0, 0>
}
