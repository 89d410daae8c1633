# Success is silent: every command that does not print, with valid values,
# prints nothing at all (stdout and stderr empty, status 0)
time_step = 0.05
collision_dist = 0.01
internal_step = 0
max_linear = 10
max_angular = 5
force = (0, 0, -1) 1
gravity
collision_sound = bell
collision_vol = 0.5
frames =
max_frames = 10
heap = 0
gps = 0
distribution = improved
lcm_url = udpm://239.255.76.67:7667?ttl=0
seed = 42
room = 0
resolution = (320, 256)
eye = (0, -4, 2)
look = (0, 0, 0.5)
up = (0, 0, 1)
ipd = 0.07
focal = 4
fov = 60
see_through = 1
reset
sphere a
  translate = (0, 0, 5)
cube b
  translate = (3, 0, 5)
  real = 1
step
step 2
start
stop
delete b
random 2
restart
