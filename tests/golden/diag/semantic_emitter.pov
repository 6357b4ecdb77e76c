// emitter belongs to a light's asos block, not an object's.
sphere { 0, 1 asos { eps 0.01 emitter panel } }
