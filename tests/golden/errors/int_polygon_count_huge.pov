// A polygon's point count beyond int.
polygon { 1e10, <0, 0>, <1, 0>, <0, 1> }
