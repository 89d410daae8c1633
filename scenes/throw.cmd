# throw.cmd — SPEC 8's select mode: a hand takes a ball from a table and
# throws it into a basket.
#
# The hand's samples are scenes/throw.trk: it comes down to the ball lying
# on the table, pulls the trigger at 0.6 s (the ball is within grab_reach of
# the hand's point), lifts it, winds up and lets go at 1.3 s moving at
# (2.5, 0, 1.273) m/s, which puts the ball 0.6 s later into the basket
# 1.5 m away (x(t) = x_r + u t + g t^2 / 2: it crosses the rim's height at
# x = 2.0, the basket's centre), where it bounces off the walls and settles.
# The held ball is kinematic: it follows the hand exactly, and the table
# and the basket are real (static) objects.
#
# Run:   vroc scenes/throw.cmd
# View:  printf 'frames = /tmp/throw\nread scenes/throw.cmd\n' | vroc
#        tools/contact-sheet /tmp/throw throw.png

time_step = 0.02
collision_dist = 0.01
max_angular = 20
gravity
default_friction = 0.3
default_elasticity = 0.4
select = 1

eye = (1.0, -3.6, 1.5)
look = (1.0, 0, 0.7)

cube floor
  size = (3, 2, 0.05)
  translate = (1, 0, -0.05)
  mass = -1
  real = 1
  color = (190, 160, 120)
cube table               # top at z = 0.76
  size = (0.4, 0.3, 0.02)
  translate = (0.2, 0, 0.74)
  mass = -1
  real = 1
  color = (140, 90, 50)
cube leg_a
  size = (0.02, 0.02, 0.36)
  translate = (-0.16, -0.26, 0.36)
  mass = -1
  real = 1
  color = (110, 70, 40)
cube leg_b
  size = (0.02, 0.02, 0.36)
  translate = (0.56, -0.26, 0.36)
  mass = -1
  real = 1
  color = (110, 70, 40)
cube leg_c
  size = (0.02, 0.02, 0.36)
  translate = (-0.16, 0.26, 0.36)
  mass = -1
  real = 1
  color = (110, 70, 40)
cube leg_d
  size = (0.02, 0.02, 0.36)
  translate = (0.56, 0.26, 0.36)
  mass = -1
  real = 1
  color = (110, 70, 40)
cube basket_front        # a 0.5 x 0.5 m basket, 0.3 m high, centred at x = 2
  size = (0.25, 0.01, 0.15)
  translate = (2, -0.26, 0.15)
  mass = -1
  real = 1
  color = (60, 120, 60)
cube basket_back
  size = (0.25, 0.01, 0.15)
  translate = (2, 0.26, 0.15)
  mass = -1
  real = 1
  color = (60, 120, 60)
cube basket_near
  size = (0.01, 0.25, 0.15)
  translate = (1.74, 0, 0.15)
  mass = -1
  real = 1
  color = (60, 120, 60)
cube basket_far
  size = (0.01, 0.25, 0.15)
  translate = (2.26, 0, 0.15)
  mass = -1
  real = 1
  color = (60, 120, 60)

sphere ball              # lying on the table
  radius = 0.06
  translate = (0.2, 0, 0.82)
  mass = 0.2
  color = (230, 80, 30)

track throw.trk
step 150
