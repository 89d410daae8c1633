# office.cmd — thesis 4.4 "Office": a workstation, a table and a bookshelf.
#
# A virtual cuboid (a red shoebox) lies on top of the bookshelf.  A small
# heavy yellow ball slides along the shelf top at 1.5 m/s and hits it; as
# heavy as the box and perfectly elastic, the ball stops dead and the box
# takes its speed (Newton's cradle), shoots off the shelf's right end, falls
# a metre onto the table beside it and knocks the objects standing there in
# several directions: the vase, the block and the apple slide off the table
# (the world is frictionless) and end on the floor; the box bounces back
# and stays on the table, near the shelf.  The room, the furniture, the books, the
# workstation and the chair (35 objects) are static models of real things
# (real = 1).
#
#   objects 43 (8 dynamic + 35 static), pairs 308 (28 + 8 x 35)
#   subframes_thesis = ceil(0.01 * 2 * 5.95 / 0.01) = 12       (table 5.1)
#
# Settings: a 1 cm envelope keeps contacts tight; 5.95 m/s is above
# anything here reaches (the box falls 1 m: 4.5 m/s), so the cap never
# changes the story.  Every real object has elasticity 0.5: impacts on the
# furniture lose energy, impacts between the virtual objects (all 1) do
# not, so things settle on surfaces but pass momentum on to each other.
# Static pieces never share a face plane where something slides (the
# shelf's sides stop below its top board): sliding over such a seam is an
# edge-on-edge impact in a frictionless, event-driven world.
#
# Run:   vroc scenes/office.cmd          (runs max_frames = 600 frames: 6 s)
# View:  printf 'frames = /tmp/office\nread scenes/office.cmd\n' | vroc
#        tools/contact-sheet /tmp/office office.png

time_step = 0.01         # 100 frames per simulated second
collision_dist = 0.01    # 1 cm envelope
max_linear = 5.95        # m/s: subframes_thesis = 12
gravity

eye = (0.2, -0.9, 1.9)
look = (-1.0, 1.5, 1.05)

# ---- the room: 5 m x 4 m, floor at z = 0 ----
cube floor
  size = (2.5, 2, 0.05)
  translate = (0, 0, -0.05)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (110, 95, 80)
cube back_wall
  size = (2.5, 0.05, 1.4)
  translate = (0, 2.05, 1.4)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (210, 205, 190)
cube left_wall
  size = (0.05, 2, 1.4)
  translate = (-2.55, 0, 1.4)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (195, 190, 175)
cube right_wall
  size = (0.05, 2, 1.4)
  translate = (2.55, 0, 1.4)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (195, 190, 175)
cube front_wall          # behind the viewer
  size = (2.5, 0.05, 1.4)
  translate = (0, -2.05, 1.4)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (195, 190, 175)

# ---- the bookshelf in the back left corner: 0.8 x 0.35 x 1.8 m ----
cube shelf_left
  size = (0.02, 0.175, 0.88)
  translate = (-2.48, 1.825, 0.88)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (120, 80, 45)
cube shelf_right
  size = (0.02, 0.175, 0.88)
  translate = (-1.72, 1.825, 0.88)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (120, 80, 45)
cube shelf_back
  size = (0.4, 0.01, 0.9)
  translate = (-2.1, 1.99, 0.9)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (100, 65, 35)
cube shelf_top           # the box lies here, top surface at z = 1.8
  size = (0.4, 0.175, 0.02)
  translate = (-2.1, 1.825, 1.78)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (135, 90, 50)
cube shelf_bottom
  size = (0.38, 0.175, 0.05)
  translate = (-2.1, 1.825, 0.05)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (120, 80, 45)
cube shelf_1
  size = (0.38, 0.175, 0.015)
  translate = (-2.1, 1.825, 0.62)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (135, 90, 50)
cube shelf_2
  size = (0.38, 0.175, 0.015)
  translate = (-2.1, 1.825, 1.2)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (135, 90, 50)
cube books_1a
  size = (0.12, 0.12, 0.13)
  translate = (-2.3, 1.84, 0.765)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (160, 40, 40)
cube books_1b
  size = (0.1, 0.12, 0.11)
  translate = (-1.9, 1.84, 0.745)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (40, 80, 150)
cube books_2a
  size = (0.15, 0.12, 0.12)
  translate = (-2.25, 1.84, 1.335)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (50, 120, 60)
cube books_2b
  size = (0.08, 0.12, 0.14)
  translate = (-1.86, 1.84, 1.355)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (180, 150, 60)
cube books_0a
  size = (0.16, 0.12, 0.13)
  translate = (-2.25, 1.84, 0.23)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (90, 50, 110)
cube books_0b
  size = (0.1, 0.12, 0.1)
  translate = (-1.92, 1.84, 0.2)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (170, 90, 40)

# ---- the table beside it: 2.0 x 0.8 m, top surface at z = 0.75 ----
cube table_top
  size = (1, 0.4, 0.02)
  translate = (-0.68, 1.6, 0.73)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (185, 150, 100)
cube table_leg1
  size = (0.025, 0.025, 0.355)
  translate = (-1.63, 1.25, 0.355)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (90, 70, 50)
cube table_leg2
  size = (0.025, 0.025, 0.355)
  translate = (0.27, 1.25, 0.355)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (90, 70, 50)
cube table_leg3
  size = (0.025, 0.025, 0.355)
  translate = (-1.63, 1.95, 0.355)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (90, 70, 50)
cube table_leg4
  size = (0.025, 0.025, 0.355)
  translate = (0.27, 1.95, 0.355)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (90, 70, 50)

# ---- the workstation at the table's right end ----
cube ws_stand
  size = (0.1, 0.1, 0.025)
  translate = (-0.1, 1.75, 0.775)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (60, 60, 65)
cube ws_monitor
  size = (0.22, 0.2, 0.19)
  translate = (-0.1, 1.75, 0.99)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (215, 210, 195)
cube ws_screen
  size = (0.18, 0.005, 0.14)
  translate = (-0.1, 1.55, 1.0)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (30, 60, 90)
cube ws_keyboard
  size = (0.22, 0.08, 0.015)
  translate = (-0.1, 1.35, 0.765)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (200, 195, 180)
cube ws_mousepad
  size = (0.09, 0.09, 0.003)
  translate = (0.2, 1.35, 0.753)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (40, 40, 120)
superquadric ws_mouse
  a1 = 0.03
  a2 = 0.05
  a3 = 0.018
  exp1 = 0.6
  exp2 = 0.8
  translate = (0.2, 1.35, 0.774)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (210, 205, 190)
cube ws_tower
  size = (0.1, 0.24, 0.23)
  translate = (0.2, 1.72, 0.98)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (120, 125, 135)

# ---- a chair in front of it and a waste bin ----
cube chair_seat
  size = (0.23, 0.22, 0.04)
  translate = (-0.1, 0.85, 0.46)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (40, 40, 45)
cube chair_back
  size = (0.21, 0.03, 0.25)
  translate = (-0.1, 0.61, 0.8)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (40, 40, 45)
cube chair_post
  size = (0.03, 0.03, 0.19)
  translate = (-0.1, 0.85, 0.23)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (80, 80, 85)
cube chair_base
  size = (0.25, 0.25, 0.02)
  translate = (-0.1, 0.85, 0.02)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (80, 80, 85)
superquadric waste_bin
  a1 = 0.14
  a2 = 0.14
  a3 = 0.17
  exp1 = 0.1
  exp2 = 1
  translate = (0.8, 1.7, 0.17)
  mass = -1
  elasticity = 0.5
  real = 1
  color = (70, 110, 70)

# ---- the virtual objects ----
sphere yellow_ball       # small and heavy (1.5 kg in 14 cm), sliding along the shelf top
  radius = 0.07
  mass = 1.5
  translate = (-2.35, 1.8, 1.875)
  linear_vel = (1.5, 0, 0)
  elasticity = 1
  color = (255, 230, 0)
cube cuboid              # the shoebox (30 x 18 x 14 cm) on the shelf top, as heavy as the ball
  size = (0.15, 0.09, 0.07)
  mass = 1.5
  translate = (-1.95, 1.8, 1.875)
  elasticity = 1
  color = (230, 60, 40)
superquadric mug         # the table's objects, standing where the box lands
  a1 = 0.045
  a2 = 0.045
  a3 = 0.06
  exp1 = 0.1
  exp2 = 1
  translate = (-1.25, 1.62, 0.815)
  mass = 0.4
  elasticity = 1
  color = (240, 240, 240)
sphere orange
  radius = 0.05
  translate = (-1.05, 1.5, 0.805)
  mass = 0.3
  elasticity = 1
  color = (255, 140, 0)
cube block
  size = (0.05, 0.05, 0.05)
  translate = (-0.8, 1.62, 0.805)
  mass = 0.5
  elasticity = 1
  color = (60, 160, 255)
superquadric vase
  a1 = 0.05
  a2 = 0.05
  a3 = 0.12
  exp1 = 0.6
  exp2 = 1
  translate = (-0.95, 1.8, 0.875)
  mass = 0.6
  elasticity = 1
  color = (150, 60, 200)
cube book
  size = (0.1, 0.14, 0.02)
  translate = (-1.45, 1.45, 0.775)
  mass = 0.8
  elasticity = 1
  color = (30, 130, 70)
sphere apple
  radius = 0.045
  translate = (-0.7, 1.85, 0.8)
  mass = 0.2
  elasticity = 1
  color = (200, 20, 30)

start                    # batch: max_frames (600 frames, 6 s): sliding things never rest
