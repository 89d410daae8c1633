# tools/fuzz/edits.py 5 switch: the heap and the workers (memq://) switched between steps;
# tests/scenes_parallel.sh runs it with those lines and without them: one dump
lcm_url = memq://
time_step = 0.05
collision_dist = 0.01
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
cube o0
 size = (0.0904209,0.0865575,0.0549432)
 translate = (-0.806664,-0.480408,1.24615)
 elasticity = 0.868445
 angular_vel = (-2.38815,-1.50402,1.3871)
 linear_vel = (-0.635849,0.734918,-0.221125)
cube o1
 size = (0.048326,0.0770472,0.047602)
 translate = (-0.896805,0.519967,1.05135)
 elasticity = 0.215481
superquadric o2
 a1 = 0.0588191
 a2 = 0.0519334
 a3 = 0.0925671
 exp1 = 1.05088
 exp2 = 0.518002
 translate = (0.843402,-0.424369,1.95812)
 elasticity = 0.383223
 angular_vel = (-0.51056,2.61476,-1.41713)
 linear_vel = (0.634801,0.172283,0.191958)
sphere o3
 radius = 0.0602738
 translate = (-0.342076,0.445925,1.37689)
 elasticity = 0.315793
 angular_vel = (1.22801,-2.65799,2.8506)
 linear_vel = (0.49959,0.689762,-0.963865)
superquadric o4
 a1 = 0.0619711
 a2 = 0.0747111
 a3 = 0.0405447
 exp1 = 0.356073
 exp2 = 0.517103
 translate = (0.819324,-0.42487,1.70688)
 elasticity = 0.929655
 linear_vel = (-0.290414,0.0494036,0.551206)
cube o5
 size = (0.0753858,0.0868592,0.0620378)
 translate = (-0.367445,-0.0938326,1.97401)
 elasticity = 0.208483
 linear_vel = (-0.703609,-0.448647,0.405213)
cube o6
 size = (0.058747,0.059008,0.0506487)
 translate = (-0.759247,-0.491585,1.62701)
 elasticity = 0.996727
 angular_vel = (-2.70869,2.92019,0.201184)
 linear_vel = (-0.525327,0.18792,0.652591)
gps = 0
step 8
superquadric o7
 a1 = 0.0600511
 a2 = 0.0524236
 a3 = 0.098878
 exp1 = 0.976857
 exp2 = 0.459332
 translate = (0.713693,-0.120649,1.50259)
 elasticity = 0.372998
 angular_vel = (-0.476125,-2.15279,2.53202)
step 6
cube table
 mass = 0.5
step 23
max_linear = 8
step 10
cube o8
 size = (0.06262,0.0993033,0.097589)
 translate = (0.228537,-0.000948569,1.70617)
 elasticity = 0.0891374
 angular_vel = (1.69211,2.20432,-0.832043)
step 25
delete o7
heap = 0
step 22
superquadric o2
 mass = 2
heap = 1
step 18
max_linear = 8
gps = 2
step 9
internal_step = 0
gps = 3
step 21
superquadric o9
 a1 = 0.0728195
 a2 = 0.0550415
 a3 = 0.0802986
 exp1 = 0.855527
 exp2 = 1.28002
 translate = (0.265386,0.416676,1.71746)
 elasticity = 0.644063
step 12
dump
