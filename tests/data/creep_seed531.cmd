
time_step = 0.02
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
 a1 = 0.0661149
 a2 = 0.0918651
 a3 = 0.045385
 exp1 = 0.854231
 exp2 = 0.64555
 translate = (-0.541231,-0.479511,1.59835)
 elasticity = 0.974471
 angular_vel = (0.100926,-2.63663,-0.681418)
sphere o1
 radius = 0.078376
 translate = (0.809025,0.232993,0.956842)
 elasticity = 0.307869
 angular_vel = (-1.42839,-0.524428,-2.74331)
 linear_vel = (-0.771571,0.539033,-0.346045)
sphere o2
 radius = 0.0542892
 translate = (0.128652,-0.0474425,1.81225)
 elasticity = 0.747464
 linear_vel = (0.198676,0.581521,-0.863212)
superquadric o3
 a1 = 0.0414328
 a2 = 0.090332
 a3 = 0.0554803
 exp1 = 0.339996
 exp2 = 0.576511
 translate = (-0.161766,0.103377,0.916967)
 elasticity = 0.185903
 linear_vel = (0.676346,0.13282,-0.233752)
superquadric o4
 a1 = 0.0627134
 a2 = 0.0984076
 a3 = 0.0581534
 exp1 = 1.49884
 exp2 = 0.699928
 translate = (0.876337,-0.18389,1.81167)
 elasticity = 0.704502
 linear_vel = (0.428255,0.31787,0.783947)
sphere o5
 radius = 0.0587581
 translate = (0.833593,-0.111173,0.813313)
 elasticity = 0.241646
cube o6
 size = (0.0424637,0.0705102,0.0644694)
 translate = (0.232561,0.592564,1.76971)
 elasticity = 0.378178
 angular_vel = (-1.04106,0.801763,1.06508)
 linear_vel = (-0.487816,0.729758,0.87974)
step 7
delete o0
step 14
sphere o7
 radius = 0.0642835
 translate = (0.276752,0.596455,1.715)
 elasticity = 0.591803
step 15
delete o7
step 9
cube table
 mass = 0.5
step 1
superquadric o8
 a1 = 0.0615153
 a2 = 0.0826605
 a3 = 0.0995719
 exp1 = 0.637024
 exp2 = 0.883464
 translate = (0.853663,0.21815,2.43045)
 elasticity = 0.114981
 linear_vel = (-0.46756,0.55973,-0.826704)
step 1
superquadric o4
 translate = (-0.0504763,-0.484301,2.22829)
step 14
seed = 59
room = 0
random 2
step 13
max_linear = 2
step 18
delete o1
step 24
dump
