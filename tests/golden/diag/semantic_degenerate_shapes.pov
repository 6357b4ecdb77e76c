cylinder { <0, 1, 0>, <0, 1, 0>, 1 }
cone { 0, 0, y, 0 }
disc { 0, <0, 0, 0>, 1 }
disc { 0, y, 1, 2 }
plane { <0, 0, 0>, 1 }
