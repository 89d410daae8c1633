# A script's start runs until everything rests or max_frames frames: a
# script never hangs.  No dynamic object: nothing to run.  A sphere in free
# fall or in free flight never rests: max_frames frames.
cube floor
  mass = -1
start
stats
# Free fall from z = 10 (time_step 0.125, exact in binary, no speed cap):
# after 4 frames t = 0.5, z = 10 - 4.9/4 = 8.775; after 8, t = 1, z = 5.1.
gravity
time_step = 0.125
max_linear = 100
max_frames = 4
sphere falling
  radius = 0.5
  translate = (0, 0, 10)
start
dump
start
dump
restart
force = (0, 0, -1) 0
max_frames = 3
sphere flying
  linear_vel = (1, 0, 0)
start
dump
stop
stop
