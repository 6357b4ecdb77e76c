// An orthographic camera; its view is sized by right and up.
camera {
  orthographic
  location <0, 10, 0>
  sky z   // looking straight down: say which way is up
  right 8 * x
  up 6 * y
  look_at <0, 0, 0>
}
