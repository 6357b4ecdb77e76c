sphere {
  0, 1
  double_illuminate
}
