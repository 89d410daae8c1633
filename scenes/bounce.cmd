# bounce.cmd — thesis 4.5 "Bounce": a chair and a pedestal with balls on them.
#
# Ten virtual balls lie on a real armchair's seat and in the rimmed tray on
# top of a real pedestal.  Two spinning pillow-shaped superquadrics are
# dropped over them: the white one lands in the chair, pushes the balls
# aside against the chair's back, arms and front rail and comes to lie on
# them like a cushion (carried by several balls at once); the yellow one
# strikes the tray's rim, jostles its balls and tumbles to the floor.  The
# balls bounce, lose energy on the furniture (elasticity 0.6) and settle
# again on the chair and the pedestal: all ten rest from frame 1076 (10.8
# s; the last slide a few cm/s on the frictionless seat and tray until a
# rail stops them), the white pillow, which rocks on the chair's balls
# before it settles, from frame 489.
# The room, chair and pedestal (23 pieces) are static models of real
# things (real = 1).
#
#   objects 35 (12 dynamic + 23 static), pairs 342 (66 + 12 x 23)
#   subframes_thesis = ceil(0.01 * 2 * 2.95 / 0.01) = 6        (table 5.1)
#
# Settings: a 1 cm envelope; a 2.95 m/s speed cap, which the pillows reach
# after a 0.44 m fall (they come down a little slowly).  The chair's front
# rail and the tray's rim keep frictionless balls from sliding off: nothing
# else would stop them.
#
# Run:   vroc scenes/bounce.cmd    (max_frames = 600 frames, 6 s: the yellow
#                                    pillow slides on the floor, never rests;
#                                    `max_frames = 1100` first to see every
#                                    ball come to rest)
# View:  printf 'frames = /tmp/bounce\nread scenes/bounce.cmd\n' | vroc
#        tools/contact-sheet /tmp/bounce bounce.png

time_step = 0.01
collision_dist = 0.01
max_linear = 2.95
gravity

eye = (0.1, -2.3, 2.0)
look = (0.1, 0.5, 0.75)

# ---- the room: floor at z = 0, walls on four sides ----
# (the floor reaches the front wall, and the side walls reach it too: when
# the floor stopped at y = -2, the yellow pillow slid off its edge at 9.7
# s and fell out of the room; when the side walls stopped there, it slid
# past the left wall's end at 12 s and off the floor's side)
cube floor
  size = (2, 3, 0.05)
  translate = (0, -1, -0.05)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (90, 110, 130)
cube back_wall
  size = (2, 0.05, 1.2)
  translate = (0, 2.05, 1.2)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (210, 205, 190)
cube left_wall
  size = (0.05, 3, 1.2)
  translate = (-2.05, -1, 1.2)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (195, 190, 175)
cube right_wall
  size = (0.05, 3, 1.2)
  translate = (2.05, -1, 1.2)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (195, 190, 175)
cube front_wall          # behind the viewer
  size = (2, 0.05, 1.2)
  translate = (0, -4.05, 1.2)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (195, 190, 175)

# ---- the armchair, seat 0.5 x 0.5 m, top surface at z = 0.45 ----
cube chair_seat
  size = (0.25, 0.25, 0.03)
  translate = (-0.5, 0.5, 0.42)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (150, 40, 40)
cube chair_back
  size = (0.31, 0.04, 0.33)
  translate = (-0.5, 0.79, 0.72)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (150, 40, 40)
cube chair_arm_left      # side panels from the seat up to the arm rests
  size = (0.03, 0.25, 0.12)
  translate = (-0.78, 0.5, 0.51)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (130, 35, 35)
cube chair_arm_right
  size = (0.03, 0.25, 0.12)
  translate = (-0.22, 0.5, 0.51)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (130, 35, 35)
cube chair_pad_left      # the arm rests
  size = (0.05, 0.27, 0.025)
  translate = (-0.78, 0.48, 0.655)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (110, 70, 40)
cube chair_pad_right
  size = (0.05, 0.27, 0.025)
  translate = (-0.22, 0.48, 0.655)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (110, 70, 40)
cube chair_rail          # the seat's raised front edge
  size = (0.25, 0.025, 0.07)
  translate = (-0.5, 0.225, 0.46)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (130, 35, 35)
cube chair_leg1
  size = (0.025, 0.025, 0.2)
  translate = (-0.75, 0.27, 0.2)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (110, 70, 40)
cube chair_leg2
  size = (0.025, 0.025, 0.2)
  translate = (-0.25, 0.27, 0.2)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (110, 70, 40)
cube chair_leg3
  size = (0.025, 0.025, 0.2)
  translate = (-0.75, 0.79, 0.2)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (110, 70, 40)
cube chair_leg4
  size = (0.025, 0.025, 0.2)
  translate = (-0.25, 0.79, 0.2)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (110, 70, 40)

# ---- the pedestal: a column with a rimmed tray on top at z = 0.9 ----
cube ped_base
  size = (0.22, 0.22, 0.03)
  translate = (0.7, 0.5, 0.03)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (220, 220, 215)
cube ped_column
  size = (0.08, 0.08, 0.42)
  translate = (0.7, 0.5, 0.46)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (235, 235, 230)
cube ped_top
  size = (0.22, 0.22, 0.02)
  translate = (0.7, 0.5, 0.88)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (220, 220, 215)
cube ped_rim_front
  size = (0.22, 0.015, 0.045)
  translate = (0.7, 0.295, 0.945)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (190, 170, 90)
cube ped_rim_back
  size = (0.22, 0.015, 0.045)
  translate = (0.7, 0.705, 0.945)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (190, 170, 90)
cube ped_rim_left
  size = (0.015, 0.19, 0.045)
  translate = (0.495, 0.5, 0.945)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (190, 170, 90)
cube ped_rim_right
  size = (0.015, 0.19, 0.045)
  translate = (0.905, 0.5, 0.945)
  mass = -1
  elasticity = 0.6
  real = 1
  color = (190, 170, 90)

# ---- six balls on the seat, four in the tray (radius 6-7 cm, 0.3 kg) ----
sphere ball1
  radius = 0.07
  mass = 0.3
  translate = (-0.62, 0.38, 0.525)
  elasticity = 0.9
  color = (230, 50, 50)
sphere ball2
  radius = 0.065
  mass = 0.3
  translate = (-0.46, 0.37, 0.520)
  elasticity = 0.9
  color = (255, 210, 40)
sphere ball3
  radius = 0.06
  mass = 0.3
  translate = (-0.33, 0.4, 0.515)
  elasticity = 0.9
  color = (60, 140, 255)
sphere ball4
  radius = 0.065
  mass = 0.3
  translate = (-0.64, 0.56, 0.520)
  elasticity = 0.9
  color = (60, 200, 90)
sphere ball5
  radius = 0.07
  mass = 0.3
  translate = (-0.48, 0.58, 0.525)
  elasticity = 0.9
  color = (240, 120, 20)
sphere ball6
  radius = 0.06
  mass = 0.3
  translate = (-0.34, 0.62, 0.515)
  elasticity = 0.9
  color = (200, 80, 220)
sphere ball7
  radius = 0.065
  mass = 0.3
  translate = (0.6, 0.4, 0.970)
  elasticity = 0.9
  color = (255, 255, 255)
sphere ball8
  radius = 0.06
  mass = 0.3
  translate = (0.8, 0.41, 0.965)
  elasticity = 0.9
  color = (40, 220, 220)
sphere ball9
  radius = 0.06
  mass = 0.3
  translate = (0.61, 0.6, 0.965)
  elasticity = 0.9
  color = (255, 120, 160)
sphere ball10
  radius = 0.065
  mass = 0.3
  translate = (0.79, 0.6, 0.970)
  elasticity = 0.9
  color = (150, 230, 60)

# ---- the two pillows, dropped spinning ----
superquadric pillow1     # over the chair
  a1 = 0.17
  a2 = 0.13
  a3 = 0.06
  exp1 = 0.5
  exp2 = 0.3
  mass = 0.5
  translate = (-0.4, 0.5, 1.5)
  rotate = (1, 0, 0) 0.3
  angular_vel = (3, 0, 0)
  elasticity = 0.8
  color = (245, 245, 250)
superquadric pillow2     # over the pedestal
  a1 = 0.15
  a2 = 0.15
  a3 = 0.05
  exp1 = 0.5
  exp2 = 0.3
  mass = 0.5
  translate = (0.8, 0.5, 1.7)
  rotate = (0, 1, 0) 0.4
  angular_vel = (0, 3, 0)
  elasticity = 0.8
  color = (250, 230, 120)

start                    # batch: until everything rests, at most max_frames (600)
