# No force: x = v t.  time_step 0.1, step 10: t = 1, x exactly 1 (the
# brief's case); time_step 0.125 is exact in binary: after 8 frames t = 1.
sphere ball
  linear_vel = (1, 0, 0)
step 10
dump
restart
time_step = 0.125
sphere ball
  linear_vel = (1, -2, 0.5)
  translate = (3, 0, -1)
step 8
dump
