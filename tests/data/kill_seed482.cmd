gps = 3
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
sphere o0
 radius = 0.0472886
 translate = (0.417426,0.398684,1.76621)
 elasticity = 0.173576
 linear_vel = (-0.594701,-0.280859,0.849338)
sphere o1
 radius = 0.0711278
 translate = (0.678462,0.570808,1.30813)
 elasticity = 0.951338
 angular_vel = (-0.435163,-2.18371,1.09887)
 linear_vel = (0.651471,0.185947,0.0074799)
cube o2
 size = (0.0616676,0.0410411,0.0839608)
 translate = (0.0107479,0.275939,0.876279)
 elasticity = 0.0477944
 angular_vel = (-0.41557,-2.61933,-0.759156)
sphere o3
 radius = 0.0504375
 translate = (0.425077,0.140793,1.14903)
 elasticity = 0.21941
superquadric o4
 a1 = 0.0542898
 a2 = 0.0501397
 a3 = 0.0724516
 exp1 = 0.51635
 exp2 = 1.22994
 translate = (0.383764,0.559483,1.397)
 elasticity = 0.670026
 angular_vel = (0.213162,-0.732659,-1.01161)
 linear_vel = (0.850797,0.510352,0.778272)
sphere o5
 radius = 0.0770592
 translate = (-0.47316,0.203843,1.28266)
 elasticity = 0.609689
 angular_vel = (-1.90264,0.706247,1.60258)
 linear_vel = (-0.288505,0.363967,0.842332)
cube o6
 size = (0.0848586,0.0981549,0.0752179)
 translate = (0.0478654,-0.0945959,0.852375)
 elasticity = 0.0637797
 angular_vel = (0.0232325,-0.763565,2.37294)
step 3
cube table
 mass = -1
step 21
force = (-0.243228,-0.0962993,-1) 10.4058
step 22
superquadric o4
 linear_vel = (0.165471,-0.607059,0.916698)
step 25
time_step = 0.05
step 20
delete o0
step 7
sphere o5
 translate = (0.0564429,0.0644843,1.52563)
step 19
superquadric o7
 a1 = 0.0897121
 a2 = 0.048339
 a3 = 0.085917
 exp1 = 1.21428
 exp2 = 0.981225
 translate = (0.438166,0.0672086,1.56366)
 elasticity = 0.423816
 angular_vel = (2.53813,-2.1484,1.28469)
 linear_vel = (-0.860221,0.521123,0.880915)
step 6
superquadric o8
 a1 = 0.0988127
 a2 = 0.0421598
 a3 = 0.0985316
 exp1 = 0.323129
 exp2 = 0.617979
 translate = (0.671068,0.335799,1.92771)
 elasticity = 0.689159
 angular_vel = (2.42356,1.2386,-0.114465)
 linear_vel = (0.0272895,-0.977189,-0.773599)
step 2
superquadric o9
 a1 = 0.0447673
 a2 = 0.0681693
 a3 = 0.0435602
 exp1 = 1.33455
 exp2 = 0.417173
 translate = (-0.19781,0.0451974,1.73163)
 elasticity = 0.457026
 linear_vel = (0.245409,0.845788,0.533691)
step 17
dump
