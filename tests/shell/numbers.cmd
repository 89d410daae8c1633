# Bad numbers are rejected, naming the allowed range; nothing of the line
# is applied (show a at the end: radius 0.5 and time_step untouched)
sphere a
  radius = 0.5
  radius = nan
  radius = inf
  radius = -inf
  radius = 1e999
  radius = -1e999
  radius = 0x10
  radius = 1e
  radius = 1.2.3
  radius = --1
  radius = 1,5
  radius = 
  radius = one
  radius = 0
  radius = -0.5
  radius = 2e9
  radius = 1e-400
  ures = 3.5
  ures = 1e3
  ures = 1001
  elasticity = 1.0000001
  elasticity = -0
collision_dist = 1e-400
time_step = 1e308
show a
stats
