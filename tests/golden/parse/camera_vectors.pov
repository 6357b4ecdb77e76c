// camera: explicit vectors, a sky vector, and transforms (applied last).
camera {
  perspective
  location <0, 0, -4>
  direction <0, 0, 2>
  right x * 16 / 9
  up y
  sky <0.2, 1, 0>
  look_at <1, 0, 0>
  rotate <0, 10, 0>
  translate <0, 1, 0>
}
