# read by sub/level1.cmd
sphere deep
  radius = -1
  translate = (1, 2, 3)
  file = ../shapes/tetra.off
polyhedron shape
  file = ../shapes/tetra.off
read nowhere.cmd
