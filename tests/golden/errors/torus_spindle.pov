// A spindle torus (minor radius above the major) is refused.
torus { 1, 1.5 }
