// A camera's transforms that overflow.
camera { location -5*z look_at 0 translate 1e308*x translate 1e308*x }
