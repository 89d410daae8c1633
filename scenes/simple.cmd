# simple.cmd — thesis 5.2 "Simple": three spheres bouncing on a tabletop.
#
# The thesis used it to measure the most a frame can cost when the
# collision work is nearly nothing (table 5.1: 4 objects, 6 pairs,
# 6 subframes).  The real object is the top of a table (static, real = 1);
# three balls of different sizes and elasticities are dropped straight down
# on it from different heights, bounce lower each time and come to rest on
# it: all rest by frame 268 (2.7 s).  They are dropped straight: a frictionless
# ball given any sideways speed would slide off the edge.
#
#   objects 4 (3 dynamic + 1 static), pairs 6 (3 ball-ball + 3 ball-table)
#   subframes_thesis = ceil(time_step * 2 * max_linear / collision_dist)
#                    = ceil(0.01 * 2 * 2.95 / 0.01) = 6        (table 5.1)
#
# Run:   vroc scenes/simple.cmd            (batch: runs until all rest)
# View:  printf 'frames = /tmp/simple\nread scenes/simple.cmd\n' | vroc
#        tools/contact-sheet /tmp/simple simple.png

time_step = 0.01         # 100 frames per simulated second
collision_dist = 0.01    # 1 cm envelope for the schedule; balls rest at the 1 mm contact gap
max_linear = 2.95        # m/s: a ball stops accelerating after a 0.44 m fall
gravity

# the view: a little in front of the table, looking at its middle
eye = (0, -1.9, 1.5)
look = (0, 0, 0.9)

cube table_top           # a real 1.6 m x 1.0 m table top, 4 cm thick, 0.76 m high
  size = (0.8, 0.5, 0.02)
  translate = (0, 0, 0.74)
  mass = -1
  real = 1
  elasticity = 0.8
  color = (190, 140, 90)

sphere ball1             # red, dropped from 0.45 m above the table
  radius = 0.1
  translate = (-0.45, 0.05, 1.31)
  elasticity = 0.8
  color = (230, 50, 50)

sphere ball2             # blue, smallest, dropped highest: bounces longest
  radius = 0.07
  translate = (0.05, 0.15, 1.5)
  elasticity = 0.85
  color = (60, 140, 255)

sphere ball3             # yellow, largest, dropped lowest
  radius = 0.13
  translate = (0.45, -0.12, 1.15)
  elasticity = 0.7
  color = (255, 210, 40)

start                    # batch: until every ball rests (or max_frames)
