# SPEC 11: every input, however large or small, a sane result or a clear
# error (man vroc, LIMITS).  The cases of issue 29, each refused at its
# line, and the limits themselves accepted.
sphere a
mass = 1e300
mass = 1e12
mass = 1e-9
mass = 1e-10
mass = -1e300
linear_vel = (1e200, 0, 0)
linear_vel = (1e6, 0, -1e6)
angular_vel = (0, 1.1e6, 0)
radius = 1e-100
radius = 1e-400
radius = 1e-6
radius = 1e6
radius = 2e6
translate = (0, 0, 1.5e6)
volume = 1e13
cube c
size = (1, 1e-7, 1)
superquadric q
a3 = 1e7
lcm_url = foo
time_step = 1
internal_step = 1e-7
internal_step = 1e-6
show a
# the heaviest, fastest ball allowed into the lightest: the frame of
# time_step 1 s at 1e6 m/s against collision_dist 0.25 would need 8e6
# internal steps, and is refused before anything moves
restart
internal_step = 0
max_linear = 1e6
sphere heavy
mass = 1e12
radius = 0.1
linear_vel = (1e6, 0, 0)
sphere light
mass = 1e-9
radius = 0.1
translate = (3, 0, 0)
step
dump
# a shorter frame is fine (8e5 steps): the light ball, hit at 1e6 m/s,
# cannot leave faster than the cap, max_linear: it goes along at 1e6 m/s
time_step = 0.1
step
dump
