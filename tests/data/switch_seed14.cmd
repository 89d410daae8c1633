# tools/fuzz/edits.py 14 switch: the heap and the workers (memq://) switched between steps;
# tests/scenes_parallel.sh runs it with those lines and without them: one dump
lcm_url = memq://
time_step = 0.02
collision_dist = 0.005
max_frames = 0
gravity
cube floor
 size = (3, 3, 0.1)
 translate = (0, 0, -0.1)
 mass = -1
cube table
 size = (1, 0.8, 0.05)
 translate = (0, 0, 0.5)
 mass = -1
 elasticity = 0.3
sphere o0
 radius = 0.0553465
 translate = (0.421307,0.22183,1.16359)
 elasticity = 0.684233
 angular_vel = (1.6651,-2.2896,-1.6604)
superquadric o1
 a1 = 0.088471
 a2 = 0.0616402
 a3 = 0.0779637
 exp1 = 0.919522
 exp2 = 0.493261
 translate = (0.297778,-0.314538,0.812726)
 elasticity = 0.0699368
 linear_vel = (-0.451891,0.708158,-0.23624)
sphere o2
 radius = 0.099426
 translate = (-0.110434,0.150544,1.84711)
 elasticity = 0.686884
 angular_vel = (0.534505,0.802376,-1.91281)
 linear_vel = (0.749588,0.0275629,-0.612323)
superquadric o3
 a1 = 0.077447
 a2 = 0.0690843
 a3 = 0.0568795
 exp1 = 0.605544
 exp2 = 0.445422
 translate = (0.898614,-0.309916,0.941935)
 elasticity = 0.161716
 angular_vel = (1.11719,0.515662,-0.448868)
cube o4
 size = (0.072091,0.06731,0.0690923)
 translate = (-0.113323,0.133625,0.913825)
 elasticity = 0.474518
 angular_vel = (2.19272,2.63412,-2.60131)
 linear_vel = (0.406942,0.142894,-0.961788)
gps = 1
step 7
superquadric o3
 mass = 2
gps = 1
step 16
sphere o0
 linear_vel = (0.0601537,-0.914409,0.119766)
heap = 0
step 9
cube o5
 size = (0.0515434,0.0415111,0.0400219)
 translate = (0.0120024,0.0302015,2.26554)
 elasticity = 0.989795
 angular_vel = (2.73868,1.64971,-2.98931)
 linear_vel = (0.00133415,-0.635197,-0.584296)
heap = 1
step 22
cube table
 translate = (0, 0, 0.4)
gps = 0
step 25
force = (0.036668,0.0575028,-1) 11.3077
step 25
superquadric o1
 translate = (-0.213648,-0.11589,2.44797)
gps = 3
step 18
time_step = 0.02
step 20
cube o4
 mass = 0.5
gps = 2
step 25
delete o2
step 4
dump
