# args: @
# Type-specific attributes on another type are ignored, with a note that
# names the file and line (as in the thesis); notes are not errors.
cube box
  radius = 2
  ures = 5
  vres = 5
  exp1 = 1.5
  exp2 = 1.5
  a1 = 2
  a2 = 2
  a3 = 2
  file = shapes/tetra.off
sphere ball
  size = (2, 2, 2)
  exp1 = 1.5
polyhedron p
  ures = 5
superquadric q
  radius = 3
  size = (1, 1, 1)
show box
