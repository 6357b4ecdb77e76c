#declare A = sqrt(-1);
#declare B = log(0);
#declare C = vnormalize(<0, 0, 0>);
#declare D = acos(2);
