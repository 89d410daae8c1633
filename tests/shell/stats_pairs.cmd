# stats: 3 dynamic + 1 static objects: pairs = 3 (dynamic-dynamic) + 3
# (dynamic-static); subframes_thesis = ceil(time_step*2*max_linear/d) =
# ceil(0.1*2*8/0.25) = ceil(6.4) = 7, then ceil(0.5*2*3/0.2) = 15.
# energy: 1/2 m v^2 = 1/2 * 2 * 3^2 = 9.
sphere a
  translate = (-5, 0, 0)
  mass = 2
  linear_vel = (3, 0, 0)
sphere b
  translate = (5, 0, 0)
cube c
  translate = (0, 5, 0)
cube wall
  translate = (0, -5, 0)
  mass = -1
stats
time_step = 0.5
max_linear = 3
collision_dist = 0.2
stats
