# restart removes objects and resets time, frames and statistics, keeping
# settings (subframes_thesis = ceil(0.5*2*8/0.25) = 32 before and after)
time_step = 0.5
sphere a
  linear_vel = (1, 0, 0)
step 2
stats
restart
stats
dump
sphere a
dump
