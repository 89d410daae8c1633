# A table made dynamic under a stack of bodies chatters: 259 responses at one
# instant, past SPEC 3.1's cap of 64, so later ones come from bisections whose
# untested lower end is itself the event.  Edit fuzzer seed 2595 (tools/fuzz);
# heap on and off must give the same bits (scenes.sh).

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
sphere o0
 radius = 0.046399
 translate = (0.602119,0.699098,1.15997)
 elasticity = 0.902645
 linear_vel = (-0.487412,0.830233,0.205029)
cube o1
 size = (0.0575646,0.0719213,0.0414852)
 translate = (-0.896857,0.21208,1.25639)
 elasticity = 0.283997
cube o2
 size = (0.0898686,0.0712474,0.0413207)
 translate = (-0.666307,0.682298,0.941593)
 elasticity = 0.765977
cube o3
 size = (0.0604617,0.0441189,0.0679419)
 translate = (-0.824238,-0.588723,0.977172)
 elasticity = 0.432182
 linear_vel = (-0.93962,-0.0222099,0.768934)
superquadric o4
 a1 = 0.0791845
 a2 = 0.0858884
 a3 = 0.0710672
 exp1 = 0.36142
 exp2 = 1.11699
 translate = (-0.88991,-0.0122793,1.49023)
 elasticity = 0.297933
 angular_vel = (1.25005,-2.91568,2.11809)
superquadric o5
 a1 = 0.0653795
 a2 = 0.0787512
 a3 = 0.0727649
 exp1 = 1.01128
 exp2 = 1.19563
 translate = (0.0872253,-0.310347,0.91106)
 elasticity = 0.673159
step 10
sphere o0
 linear_vel = (-0.133691,-0.399847,0.596961)
step 14
cube table
 mass = 0.5
step 1
sphere o0
 linear_vel = (0.350416,-0.379412,-0.829422)
step 3
superquadric o4
 mass = 2
step 8
cube o3
 translate = (-0.00613393,0.0885081,1.31826)
step 22
superquadric o4
 linear_vel = (-0.78034,-0.983289,0.746529)
step 14
cube o6
 size = (0.0461077,0.0428363,0.0501787)
 translate = (-0.374973,0.34191,1.39871)
 elasticity = 0.725528
 angular_vel = (-0.245716,-0.426627,-0.41221)
 linear_vel = (-0.791687,-0.293433,0.802174)
step 22
cube o1
 translate = (-0.531604,-0.334333,2.32595)
step 4
collision_dist = 0.005
step 5
dump
