# demo.cmd — what `make demo` shows: three balls and a box fall on a table.
# tools/demo.sh sets `frames = DIR` (which opens the display) and then reads
# this file: frame 0 is the initial state, then 39 frames of 0.05 s (2 s in
# all), 40 stereo pairs of 480x384 (44 MB of PPM).
resolution = (480, 384)
eye = (0, -2.8, 2.2)
look = (0, 0, 0.8)
time_step = 0.05
collision_dist = 0.01
max_angular = 50             # the thesis's 4 rad/s would cut the box's tumble (and a note says so)
gravity

cube table
  size = (1.2, 0.7, 0.05)
  translate = (0, 0, 0.5)
  mass = -1                  # static: a model of a real table
  color = (150, 100, 55)

sphere ball1
  radius = 0.12
  translate = (-0.5, 0, 1.4)
  elasticity = 0.8
  color = (255, 60, 60)

sphere ball2
  radius = 0.1
  translate = (0.1, 0.2, 1.9)
  linear_vel = (0.3, -0.2, 0)
  elasticity = 0.6
  color = (60, 200, 255)

sphere ball3
  radius = 0.15
  translate = (0.55, -0.15, 1.1)
  elasticity = 0.9
  color = (255, 220, 40)

cube box
  size = (0.15, 0.15, 0.15)
  translate = (-0.1, -0.2, 1.6)
  rotate = (1, 1, 0) 0.5
  angular_vel = (0, 0, 1)
  elasticity = 0.5
  color = (80, 220, 120)

refresh                      # frame 000000: the initial state
step 39
