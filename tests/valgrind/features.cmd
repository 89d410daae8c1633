# tests/valgrind/features.cmd — every feature but the drawing, for
# tests/valgrind.sh (SPEC 11: valgrind finds nothing).  Not a golden: what
# it prints is not compared, only valgrind's verdict.  Errors are on purpose.
time_step = 0.02
collision_dist = 0.05
gravity
default_friction = 0.3
default_elasticity = 0.6

# objects of every kind, real and virtual, with every attribute
cube floor
  size = (4, 4, 0.1)
  translate = (0, 0, -0.1)
  mass = -1
  real = 1
sphere ball
  radius = 0.2
  translate = (0, 0, 1)
  linear_vel = (0.5, 0, 0)
  angular_vel = (0, 1, 0)
  ures = 8
  vres = 6
  color = (200, 10, 10)
cube box
  size = (0.2, 0.3, 0.2)
  translate = (1, 0, 0.5)
  rotate = (1, 1, 0) 0.3
  mass = 2
superquadric sq
  exp1 = 0.5
  exp2 = 1.5
  a1 = 0.2
  a2 = 0.3
  a3 = 0.25
  translate = (-1, 0, 0.6)
  volume = 0.1
polyhedron tetra
  file = ../shell/shapes/tetra.off
  translate = (0, 1, 0.6)
polyhedron cube_off
  file = ../data/cube.off
  translate = (0, -3, 4)
  elasticity = 0.2

# errors: the OFF reader's, the parser's, the ranges', the library's
polyhedron dent
  file = ../data/dented_cube.off
  file = no_such_file.off
delete dent
polyhedron
sphere 9bad
radius = -1
elasticity = 2
size = (1, 2)
nosuch = 3
step 0
show nobody
delete nobody
read no_such_script.cmd
help radius
help
show box

# time: the heap on and off, steps, start, the machine-readable output
step 10
dump
stats
heap = 0
step 5
heap = 1
max_frames = 20
start
stop
dump

# the random scene in a room, workers in this process (memq://)
restart
seed = 7
room = 3
random 12
lcm_url = memq://
gps = 2
distribution = improved
step 8
stats
gps = 0
step 2
delete r3
dump

# the merged environment and save: a track file, collision sounds, a save
# read back in a fresh world
restart
gravity
time_step = 0.05
sound_log = vg_sounds.log
cube floor
  size = (1, 1, 0.1)
  mass = -1
sphere ball
  radius = 0.1
  translate = (0, 0, 0.6)
  elasticity = 0.5
track hand.trk
step 20
show head
show hand
save vg.save
restart
read vg.save
step 5
dump
sound_log =
restart
quit
