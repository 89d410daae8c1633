# desks.cmd — thesis 4.2 "Computer Desks": a corner of the UNC graphics lab.
#
# Three workstations (monitor on a tilt stand, screen, keyboard, mouse on a
# pad, tower case) stand on a long table against the back wall; a printer
# sits at the table's right end and a waste bin on the floor.  These, the
# table and the floor and walls of the corner are 31 static models of real
# objects (real = 1).  Twelve virtual objects (spheres, cubes,
# superquadrics) start above the computers; gravity pulls them down onto
# the monitors, towers, keyboards, printer and table, where they bounce,
# tumble and settle.  A ball lands on a box that landed on a monitor
# first; another clips monitor 1's edge and drops beside it onto the
# table, where it slides (frictionless) to and fro between the left wall
# and workstation 1, each bounce (e = 0.6) slower, until one comes in
# slower than v_rest (0.14 m/s) and does not bounce: all rest by frame
# 978 (9.8 s), so a batch run stops at max_frames (600) with that ball
# still sliding (`vroc -e 'max_frames = 1000' scenes/desks.cmd` to see
# it stop).
#
#   objects 43 (12 dynamic + 31 static), pairs 438 (66 + 12 x 31)
#   subframes_thesis = ceil(0.01 * 2 * 1.99 / 0.02) = 2        (table 5.1)
#
# The thesis's 2 subframes need a slow world or a thick envelope: here a
# 2 cm collision distance (for the schedule: objects rest at the 1 mm
# contact gap, min(collision_dist, 1 mm), SPEC 7) and a
# 2 m/s speed cap (things stop accelerating after a 20 cm fall).
#
# Run:   vroc scenes/desks.cmd
# View:  printf 'frames = /tmp/desks\nread scenes/desks.cmd\n' | vroc
#        tools/contact-sheet /tmp/desks desks.png

time_step = 0.01
collision_dist = 0.02
max_linear = 1.99
gravity

eye = (-0.2, -3.0, 2.2)
look = (-0.2, 0.4, 0.95)
fov = 58                 # wide enough for the whole 4 m table

# ---- the room: floor, back wall (y = 0.8), left wall (x = -2.2) ----
cube floor
  size = (3, 2.5, 0.05)
  translate = (0, -1, -0.05)
  mass = -1
  real = 1
  color = (90, 90, 100)
cube back_wall
  size = (3, 0.05, 1.5)
  translate = (0, 0.85, 1.5)
  mass = -1
  real = 1
  color = (200, 200, 185)
cube left_wall
  size = (0.05, 2.5, 1.5)
  translate = (-2.25, -1, 1.5)
  mass = -1
  real = 1
  color = (185, 185, 170)

# ---- the lab table: 4 m x 0.8 m, top surface at z = 0.76 ----
cube table_top
  size = (2, 0.4, 0.02)
  translate = (-0.2, 0.4, 0.74)
  mass = -1
  real = 1
  color = (170, 150, 120)
cube table_leg1
  size = (0.025, 0.025, 0.36)
  translate = (-2.15, 0.05, 0.36)
  mass = -1
  real = 1
  color = (110, 110, 110)
cube table_leg2
  size = (0.025, 0.025, 0.36)
  translate = (1.75, 0.05, 0.36)
  mass = -1
  real = 1
  color = (110, 110, 110)
cube table_leg3
  size = (0.025, 0.025, 0.36)
  translate = (-2.15, 0.75, 0.36)
  mass = -1
  real = 1
  color = (110, 110, 110)
cube table_leg4
  size = (0.025, 0.025, 0.36)
  translate = (1.75, 0.75, 0.36)
  mass = -1
  real = 1
  color = (110, 110, 110)

# ---- workstation 1, centred at x = -1.55 ----
cube ws1_stand        # tilt-swivel base
  size = (0.1, 0.1, 0.025)
  translate = (-1.55, 0.5, 0.785)
  mass = -1
  real = 1
  color = (60, 60, 65)
cube ws1_monitor      # 19-inch CRT: 0.4 x 0.38 x 0.36 m
  size = (0.2, 0.19, 0.18)
  translate = (-1.55, 0.5, 0.99)
  mass = -1
  real = 1
  color = (215, 210, 195)
cube ws1_screen       # the glass, just proud of the front face
  size = (0.16, 0.005, 0.13)
  translate = (-1.55, 0.31, 1.0)
  mass = -1
  real = 1
  color = (30, 60, 90)
cube ws1_keyboard
  size = (0.22, 0.08, 0.015)
  translate = (-1.55, 0.13, 0.775)
  mass = -1
  real = 1
  color = (200, 195, 180)
cube ws1_mousepad
  size = (0.1, 0.09, 0.003)
  translate = (-1.19, 0.13, 0.763)
  mass = -1
  real = 1
  color = (40, 40, 120)
superquadric ws1_mouse
  a1 = 0.03
  a2 = 0.05
  a3 = 0.018
  exp1 = 0.6
  exp2 = 0.8
  translate = (-1.19, 0.13, 0.784)
  mass = -1
  real = 1
  color = (210, 205, 190)
cube ws1_tower        # the workstation itself: a tower case
  size = (0.1, 0.22, 0.22)
  translate = (-1.17, 0.55, 0.98)
  mass = -1
  real = 1
  color = (120, 125, 135)

# ---- workstation 2, centred at x = -0.45 ----
cube ws2_stand        # tilt-swivel base
  size = (0.1, 0.1, 0.025)
  translate = (-0.45, 0.5, 0.785)
  mass = -1
  real = 1
  color = (60, 60, 65)
cube ws2_monitor      # 19-inch CRT: 0.4 x 0.38 x 0.36 m
  size = (0.2, 0.19, 0.18)
  translate = (-0.45, 0.5, 0.99)
  mass = -1
  real = 1
  color = (215, 210, 195)
cube ws2_screen       # the glass, just proud of the front face
  size = (0.16, 0.005, 0.13)
  translate = (-0.45, 0.31, 1.0)
  mass = -1
  real = 1
  color = (30, 60, 90)
cube ws2_keyboard
  size = (0.22, 0.08, 0.015)
  translate = (-0.45, 0.13, 0.775)
  mass = -1
  real = 1
  color = (200, 195, 180)
cube ws2_mousepad
  size = (0.1, 0.09, 0.003)
  translate = (-0.09, 0.13, 0.763)
  mass = -1
  real = 1
  color = (40, 40, 120)
superquadric ws2_mouse
  a1 = 0.03
  a2 = 0.05
  a3 = 0.018
  exp1 = 0.6
  exp2 = 0.8
  translate = (-0.09, 0.13, 0.784)
  mass = -1
  real = 1
  color = (210, 205, 190)
cube ws2_tower        # the workstation itself: a tower case
  size = (0.1, 0.22, 0.22)
  translate = (-0.07, 0.55, 0.98)
  mass = -1
  real = 1
  color = (120, 125, 135)

# ---- workstation 3, centred at x = 0.65 ----
cube ws3_stand        # tilt-swivel base
  size = (0.1, 0.1, 0.025)
  translate = (0.65, 0.5, 0.785)
  mass = -1
  real = 1
  color = (60, 60, 65)
cube ws3_monitor      # 19-inch CRT: 0.4 x 0.38 x 0.36 m
  size = (0.2, 0.19, 0.18)
  translate = (0.65, 0.5, 0.99)
  mass = -1
  real = 1
  color = (215, 210, 195)
cube ws3_screen       # the glass, just proud of the front face
  size = (0.16, 0.005, 0.13)
  translate = (0.65, 0.31, 1.0)
  mass = -1
  real = 1
  color = (30, 60, 90)
cube ws3_keyboard
  size = (0.22, 0.08, 0.015)
  translate = (0.65, 0.13, 0.775)
  mass = -1
  real = 1
  color = (200, 195, 180)
cube ws3_mousepad
  size = (0.1, 0.09, 0.003)
  translate = (1.01, 0.13, 0.763)
  mass = -1
  real = 1
  color = (40, 40, 120)
superquadric ws3_mouse
  a1 = 0.03
  a2 = 0.05
  a3 = 0.018
  exp1 = 0.6
  exp2 = 0.8
  translate = (1.01, 0.13, 0.784)
  mass = -1
  real = 1
  color = (210, 205, 190)
cube ws3_tower        # the workstation itself: a tower case
  size = (0.1, 0.22, 0.22)
  translate = (1.03, 0.55, 0.98)
  mass = -1
  real = 1
  color = (120, 125, 135)

# ---- the rest of the corner ----
cube printer
  size = (0.24, 0.2, 0.1)
  translate = (1.48, 0.55, 0.86)
  mass = -1
  real = 1
  color = (230, 230, 225)
superquadric waste_bin   # a cylinder: flat ends (exp1 small), round plan
  a1 = 0.15
  a2 = 0.15
  a3 = 0.18
  exp1 = 0.1
  exp2 = 1
  translate = (1.2, -0.3, 0.18)
  mass = -1
  real = 1
  color = (70, 110, 70)

# ---- twelve virtual objects above the computers ----
sphere ball1             # onto workstation 1's monitor
  radius = 0.08
  translate = (-1.55, 0.5, 1.75)
  elasticity = 0.6
  color = (230, 50, 50)
cube box1                # onto workstation 1's tower, turning
  size = (0.07, 0.07, 0.07)
  translate = (-1.17, 0.55, 1.6)
  rotate = (0, 0, 1) 0.4
  angular_vel = (2, 0, 0)
  elasticity = 0.5
  color = (255, 140, 30)
superquadric blob1       # a rounded cube onto workstation 1's keyboard
  a1 = 0.06
  a2 = 0.06
  a3 = 0.06
  exp1 = 0.4
  exp2 = 0.4
  translate = (-1.6, 0.13, 1.3)
  rotate = (1, 0, 0) 0.3
  elasticity = 0.5
  color = (60, 200, 90)
sphere ball2             # clips monitor 1's left edge, drops beside it
  radius = 0.05
  translate = (-1.77, 0.5, 1.9)
  elasticity = 0.6
  color = (255, 230, 40)
cube box2                # onto workstation 2's monitor ...
  size = (0.08, 0.08, 0.08)
  translate = (-0.45, 0.5, 1.6)
  elasticity = 0.4
  color = (60, 140, 255)
sphere ball3             # ... and a ball onto that box
  radius = 0.07
  translate = (-0.45, 0.5, 2.2)
  elasticity = 0.6
  color = (240, 80, 200)
superquadric pillow1     # onto workstation 2's tower, spinning
  a1 = 0.08
  a2 = 0.08
  a3 = 0.04
  exp1 = 0.5
  exp2 = 0.3
  translate = (-0.07, 0.55, 1.7)
  angular_vel = (0, 3, 0)
  elasticity = 0.4
  color = (250, 250, 250)
sphere ball4             # onto workstation 2's keyboard
  radius = 0.06
  translate = (-0.35, 0.13, 1.2)
  elasticity = 0.7
  color = (40, 220, 220)
superquadric egg1        # an ellipsoid onto workstation 3's monitor, tilted
  a1 = 0.05
  a2 = 0.05
  a3 = 0.09
  translate = (0.65, 0.5, 1.6)
  rotate = (0, 1, 0) 0.5
  elasticity = 0.5
  color = (180, 120, 255)
cube box3                # onto workstation 3's keyboard
  size = (0.06, 0.05, 0.04)
  translate = (0.6, 0.13, 1.3)
  rotate = (0, 1, 0) 0.3
  elasticity = 0.5
  color = (255, 90, 90)
sphere ball5             # onto workstation 3's tower
  radius = 0.07
  translate = (1.03, 0.55, 1.7)
  elasticity = 0.6
  color = (120, 255, 120)
cube box4                # onto the printer
  size = (0.1, 0.08, 0.06)
  translate = (1.48, 0.55, 1.5)
  rotate = (1, 1, 0) 0.6
  angular_vel = (1, 0, 0)
  elasticity = 0.5
  color = (255, 200, 120)

start                    # batch: until everything rests (or max_frames)
