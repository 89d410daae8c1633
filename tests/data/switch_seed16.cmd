# tools/fuzz/edits.py 16 switch: the heap and the workers (memq://) switched between steps;
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
superquadric o0
 a1 = 0.0650172
 a2 = 0.0668056
 a3 = 0.0645709
 exp1 = 1.08925
 exp2 = 0.610626
 translate = (0.242993,-0.68582,1.16245)
 elasticity = 0.335063
 angular_vel = (1.46049,-1.13935,1.73545)
superquadric o1
 a1 = 0.0412224
 a2 = 0.0492376
 a3 = 0.0763629
 exp1 = 1.05715
 exp2 = 0.857675
 translate = (0.177638,0.284959,1.98252)
 elasticity = 0.782651
 angular_vel = (-0.478312,-2.48436,-0.0342432)
cube o2
 size = (0.096903,0.0575813,0.0426404)
 translate = (0.852992,0.465599,1.7484)
 elasticity = 0.523373
 angular_vel = (-2.07294,-1.17457,-0.234706)
 linear_vel = (0.39857,0.455765,-0.973864)
superquadric o3
 a1 = 0.0408393
 a2 = 0.0903932
 a3 = 0.08194
 exp1 = 0.447528
 exp2 = 1.29955
 translate = (-0.759323,0.216076,1.9617)
 elasticity = 0.70708
cube o4
 size = (0.0723532,0.079562,0.0640007)
 translate = (-0.325126,0.0155714,1.94332)
 elasticity = 0.782823
cube o5
 size = (0.0591987,0.0824545,0.0725046)
 translate = (-0.46236,-0.14796,0.855915)
 elasticity = 0.843214
 linear_vel = (0.693525,-0.214632,0.799489)
heap = 1
step 5
cube o6
 size = (0.0715242,0.095139,0.046242)
 translate = (-0.634972,-0.156335,1.3463)
 elasticity = 0.464457
 linear_vel = (-0.921929,-0.939344,-0.603595)
heap = 1
step 22
cube o6
 linear_vel = (-0.231558,0.6243,-0.77262)
heap = 0
step 21
superquadric o7
 a1 = 0.0660396
 a2 = 0.0904313
 a3 = 0.0542523
 exp1 = 1.35953
 exp2 = 1.35131
 translate = (-0.120879,-0.385174,1.52152)
 elasticity = 0.667432
step 7
max_angular = 20
gps = 2
step 10
time_step = 0.01
gps = 2
step 25
cube table
 mass = 3
gps = 2
step 16
dump
