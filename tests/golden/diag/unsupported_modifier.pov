sphere {
  0, 1
  bounded_by { sphere { 0, 2 } }
}
