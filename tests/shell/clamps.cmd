# The thesis's speed caps (max_linear 8 m/s, max_angular 4 rad/s) cut
# velocities: stats counts each cut (clamps=), and the first of a session
# that set neither cap gets a note.  A 1 kg ball thrown at 20 m/s flies at 8 and one spun at
# 10 rad/s turns at 4: energy 35.2 J (32 J of flight, 2/5 m r^2 4^2 / 2 =
# 3.2 J of spin), not 200 + 20 J; with the caps raised nothing is cut and
# the energy is 0.5 m v^2 = 200 J.
sphere fast
  linear_vel = (20, 0, 0)
sphere spun
  translate = (0, 5, 0)
  angular_vel = (0, 0, 10)
step
dump
stats
restart
max_linear = 30
max_angular = 20
sphere fast
  linear_vel = (20, 0, 0)
step
dump
stats
