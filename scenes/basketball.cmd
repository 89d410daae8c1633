# basketball.cmd — thesis 4.3 "Virtual Basketball": a regulation court.
#
# A FIBA court, 28 m x 15 m, with one basket: the backboard (1.8 x 1.05 m,
# its lower edge 2.90 m up, its face 1.20 m inside the baseline), the rim
# (inner diameter 0.45 m, 3.05 m high, 0.15 m off the board; convex pieces
# only, so a square of four bars) and the stanchion holding them: 8 static
# models of real things.  A basketball (0.6 kg, 24 cm, elasticity 0.8) is
# thrown from the free-throw line toward the basket; it comes down into the
# hoop, hits the back of the rim, falls through and bounces on the floor,
# back toward the thrower.
#
#   objects 9 (1 dynamic + 8 static), pairs 8 (the ball with each)
#   subframes_thesis = ceil(0.01 * 2 * 14.45 / 0.005) = 58     (table 5.1)
#
# The thesis's 58 subframes come from a fast ball and a thin envelope: a
# 5 mm collision distance (the rim is a thin object) and a 14.45 m/s speed
# cap (a hard throw; this one leaves the hand at about 7 m/s).
#
# Run:   vroc scenes/basketball.cmd
# View:  printf 'frames = /tmp/bb\nread scenes/basketball.cmd\n' | vroc
#        tools/contact-sheet /tmp/bb basketball.png

time_step = 0.01
collision_dist = 0.005
max_linear = 14.45
gravity

eye = (8.0, -5.6, 3.6)
look = (10.9, 0, 2.2)

cube court               # the floor: 28 x 15 m, top at z = 0, run-off around it
  size = (16, 9.5, 0.05)
  translate = (0, 0, -0.05)
  mass = -1
  real = 1
  elasticity = 0.85
  color = (225, 175, 110)
cube stanchion           # the post, 1 m behind the baseline at x = 14
  size = (0.1, 0.1, 1.75)
  translate = (15.1, 0, 1.75)
  mass = -1
  real = 1
  color = (40, 40, 150)
cube arm                 # from the post to the back of the board
  size = (1.1, 0.06, 0.06)
  translate = (13.93, 0, 3.4)
  mass = -1
  real = 1
  color = (40, 40, 150)
cube backboard           # face at x = 12.80
  size = (0.015, 0.9, 0.525)
  translate = (12.815, 0, 3.425)
  mass = -1
  real = 1
  elasticity = 0.7
  color = (235, 235, 240)
cube rim_back            # the rim: centre (12.425, 0, 3.05), a 0.45 m square inside
  size = (0.01, 0.245, 0.01)
  translate = (12.66, 0, 3.04)
  mass = -1
  real = 1
  elasticity = 0.6
  color = (255, 90, 0)
cube rim_front
  size = (0.01, 0.245, 0.01)
  translate = (12.19, 0, 3.04)
  mass = -1
  real = 1
  elasticity = 0.6
  color = (255, 90, 0)
cube rim_left
  size = (0.245, 0.01, 0.01)
  translate = (12.425, 0.235, 3.04)
  mass = -1
  real = 1
  elasticity = 0.6
  color = (255, 90, 0)
cube rim_right
  size = (0.245, 0.01, 0.01)
  translate = (12.425, -0.235, 3.04)
  mass = -1
  real = 1
  elasticity = 0.6
  color = (255, 90, 0)

sphere ball
  radius = 0.12
  mass = 0.6
  translate = (8.4, 0, 2.1)
  linear_vel = (4.6, 0, 5.4)
  elasticity = 0.8
  ures = 16
  vres = 12
  color = (230, 100, 20)

start                    # batch: max_frames (600 frames, 6 s): the ball never rests, it slides
