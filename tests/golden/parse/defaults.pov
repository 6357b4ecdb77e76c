// An empty scene: every default (camera, global settings, background).
