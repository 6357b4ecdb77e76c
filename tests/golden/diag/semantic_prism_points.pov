// The prism announces more points than it lists.
prism { 0, 1, 5, <0, 0>, <1, 0>, <0, 1>, <0, 0> }
