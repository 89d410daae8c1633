# An explicit mass wins over volume in any order; without it the mass is
# the volume.  energy = 1/2 m v^2 with v = 1 tells the mass in use.
sphere a
  linear_vel = (1, 0, 0)
  mass = 4
  volume = 10
sphere b
  translate = (5, 0, 0)
  volume = 10
  mass = 4
sphere c
  translate = (10, 0, 0)
  volume = 6
show a
show b
show c
stats
delete a
delete b
stats
