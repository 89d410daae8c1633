# time_step = 0 halts time (thesis A.1): frames count, time and poses stay
time_step = 0
sphere s
  linear_vel = (1, 0, 0)
step 3
dump
stats
