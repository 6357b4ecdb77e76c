// A union lists its objects, then its modifiers.
union {
  sphere { 0, 1 }
  translate x
  box { 0, 1 }
}
