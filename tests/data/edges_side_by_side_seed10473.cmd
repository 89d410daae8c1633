# the physics fuzzer's seed 10473 (tools/fuzz/physics.py): two boxes side by
# side with near-parallel upright edges; heap = 0 and heap = 1 parted at
# t = 0.18 s until a vertex feature was completed to its edge (canonical.c)
time_step = 0.02
collision_dist = 0.01
max_frames = 0
max_linear = 1000
max_angular = 100000
gravity
cube floor
 size = (1.6,1.6,0.1)
 translate = (0,0,-0.1)
 mass = -1
 elasticity = 0.762038
cube ceil
 size = (1.6,1.6,0.1)
 translate = (0,0,3.1)
 mass = -1
 elasticity = 0.330149
cube wx0
 size = (0.1,1.6,1.6)
 translate = (-1.6,0,1.5)
 mass = -1
 elasticity = 0.56577
cube wx1
 size = (0.1,1.6,1.6)
 translate = (1.6,0,1.5)
 mass = -1
 elasticity = 0.937907
cube wy0
 size = (1.6,0.1,1.6)
 translate = (0,-1.6,1.5)
 mass = -1
 elasticity = 0.40095
cube wy1
 size = (1.6,0.1,1.6)
 translate = (0,1.6,1.5)
 mass = -1
 elasticity = 0.356887
cube s0
 size = (0.339172,0.202079,0.116917)
 translate = (0.348918,-0.932043,1.68409)
 mass = -1
 elasticity = 0.551278
cube k0
 size = (0.131552,0.137629,0.042194200000000001)
 translate = (-0.67966080456517775,0.19510767959052822,0.048783330824860145)
 mass = 0.2
 elasticity = 0.491446
cube k1
 size = (0.12711800000000001,0.061288700000000002,0.063830899999999996)
 translate = (-0.67775418063416315,0.19510767959052822,0.15742232436567394)
 mass = 1
 elasticity = 0.0478906
sphere d0
 radius = 0.033024
 translate = (-0.33173,-0.620156,2.6755)
 mass = 10
 elasticity = 1
 rotate = (0.108521,0.213597,0.607964) 0.165468
 linear_vel = (0.428905,0.081831,-0.00441105)
 angular_vel = (-3.92165,7.94114,-3.14699)
sphere d1
 radius = 0.0530206
 translate = (0.592291,0.952344,1.96551)
 mass = 0.5
 elasticity = 0.3
 rotate = (0.117511,0.633687,0.221992) 2.15738
 linear_vel = (0.634086,-1.01981,0.172925)
cube d2
 size = (0.0555466,0.0875789,0.0429582)
 translate = (-0.26654,0.973674,0.250236)
 mass = 10
 elasticity = 0.300092
 linear_vel = (-1.41681,-3.91698,-0.301028)
cube d3
 size = (0.073269,0.0528932,0.05557)
 translate = (0.438662,-0.164497,0.736314)
 mass = 10
 elasticity = 1
 linear_vel = (-1.75105,1.04852,-2.12385)
 angular_vel = (-2.41388,-2.72358,3.11616)
superquadric d4
 a1 = 0.106511
 a2 = 0.0582334
 a3 = 0.0705026
 exp1 = 0.796806
 exp2 = 1.25248
 translate = (0.873268,0.994961,2.38439)
 mass = 10
 elasticity = 0
 linear_vel = (-3.49829,2.09491,-1.36243)
cube d5
 size = (0.0227151,0.0200311,0.109485)
 translate = (-0.883396,-1.05673,0.743128)
 mass = 1
 elasticity = 0.8
 linear_vel = (0.0239558,0.136018,-0.19409)
 angular_vel = (5.8391,-4.16542,-0.0861598)
superquadric d6
 a1 = 0.0734588
 a2 = 0.0867702
 a3 = 0.051049
 exp1 = 0.904687
 exp2 = 1.33447
 translate = (-0.886872,0.458425,1.67306)
 mass = 0.5
 elasticity = 0.8
 rotate = (0.688311,0.14018,-0.317321) 0.449923
 linear_vel = (0.378305,0.387396,0.343947)
superquadric d7
 a1 = 0.103795
 a2 = 0.0364054
 a3 = 0.0564959
 exp1 = 0.652905
 exp2 = 0.829376
 translate = (0.250382,0.358125,2.41251)
 mass = 10
 elasticity = 0.3
 linear_vel = (-0.191422,-0.00057939,0.254704)
 angular_vel = (-4.05695,3.27631,0.738718)
start
stats
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
stats
start
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
stats
start
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
step 1
dump
stats
start
