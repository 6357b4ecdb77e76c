// prism: each spline kind as Bezier pieces (linear, quadratic, cubic,
// bezier), sub-prisms, open, sturm, heights written high first.
prism { 0, 1, 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> }
prism {
  linear_sweep linear_spline -1, 2, 10,
  <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>,
  <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>, <-0.5, 0.5>, <-0.5, -0.5>
  open
  translate x
}
prism { quadratic_spline 1, 0, 6, <-1, 0>, <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1> }
prism { cubic_spline 0, 0.5, 7, <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>, <0, 1> sturm }
prism {
  bezier_spline 0, 1, 8,
  <0, 0>, <1, 0>, <1, 1>, <1, 1>,
  <1, 1>, <0, 1>, <0, 0.5>, <0, 0>
}
