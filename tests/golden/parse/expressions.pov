// Expressions fully evaluated: operators, built-ins, functions, members.
#declare A = 2;
#declare V = <1, 2, 3>;
sphere { V * A + x, A / 4 }
sphere { <pi, sqrt(2), pow(2, 0.5)>, abs(-1) }
sphere { <sin(pi / 6), cos(0), tan(0)>, max(0.5, 0.25, 0.1) }
sphere { <asin(1), acos(1), atan2(1, 2)>, min(3, 1) }
sphere { <mod(7, 3), floor(-1.5), ceil(1.2)>, int(2.7) }
sphere { <radians(180), degrees(pi / 2), exp(1)>, log(10) }
sphere { vcross(x, y) + vnormalize(<3, 4, 0>), vlength(<3, 4, 0>) }
sphere { vrotate(x, <0, 0, 90>), vdot(V, V) }
sphere { <V.x, V.y, V.z> - <V.z, V.y, V.x>, (A > 1 ? 1 : 2) }
sphere { <(1 < 2), (1 = 1 & 2 != 3), (0 | 1)>, 1 + (!0) }
sphere { -V, select(-1, 1, 2) }
sphere { <clock, version, image_width / image_height>, 1 }
sphere { <true, yes, on>, 1 + off + no + false }
sphere { <(t + u).x, (u + v).v, (t + v).t>, 1 }
