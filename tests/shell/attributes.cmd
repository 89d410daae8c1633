# Every attribute of tables A.1-A.4 (and file, real) lands in the object's
# definition: show prints them back in a fixed order.
sphere s
  linear_vel = (1, 2, 3)
  angular_vel = (0.5, -0.25, 0)
  elasticity = 0.75
  mass = 2.5
  volume = 3
  translate = (-1, 0.5, 2)
  rotate = (0, 1, 0) 0.5
  color = (10, 20, 30)
  radius = 0.125
  ures = 12
  vres = 7
  real = 1
cube c
  size = (0.5, 1, 1.5)
  elasticity = 0
  mass = -1
superquadric q
  exp1 = 0.05
  exp2 = 2
  a1 = 0.5
  a2 = 1.5
  a3 = 2
  ures = 3
  vres = 1000
polyhedron p
  file = shapes/tetra.off      # relative to this file; a comment after a path
show s
show c
show q
show p
