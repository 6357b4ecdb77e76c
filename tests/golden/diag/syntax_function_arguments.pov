// vrotate takes two arguments.
#declare V = vrotate(<1, 0, 0>);
