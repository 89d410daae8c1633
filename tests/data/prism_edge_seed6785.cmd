# The edit fuzzer's seed 6785 (tools/fuzz/edits.py), to frame 12: a prism (h1)
# slides off the floor's edge under a force; the run saves at frame 32
# (tests/save.sh), and one of the walk's starts measured 3.4e-13 m
# longer than the other at the impact's bisection (src/contact.c).

time_step = 0.05
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
 radius = 0.0431828
 translate = (-0.142582,-0.460638,1.23003)
 elasticity = 0.114343
 angular_vel = (-2.66241,0.681401,-1.71095)
sphere o1
 radius = 0.0729267
 translate = (-0.161757,0.284748,0.925577)
 elasticity = 0.851633
 angular_vel = (-2.51515,-2.94348,-1.5323)
 linear_vel = (0.362005,-0.330215,-0.98256)
superquadric o2
 a1 = 0.0757933
 a2 = 0.0594361
 a3 = 0.0729515
 exp1 = 0.801167
 exp2 = 0.460024
 translate = (-0.810978,0.0115423,1.55868)
 elasticity = 0.506131
 angular_vel = (-1.17575,-0.885775,-0.829533)
 linear_vel = (0.892881,-0.0648022,-0.533999)
superquadric o3
 a1 = 0.0744007
 a2 = 0.0656798
 a3 = 0.0467753
 exp1 = 1.17176
 exp2 = 1.45592
 translate = (0.0568885,-0.176085,1.27837)
 elasticity = 0.927257
 angular_vel = (-0.975161,-1.26434,0.0230702)
cube o4
 size = (0.0954708,0.0722745,0.0891271)
 translate = (0.5987,-0.292568,0.932099)
 elasticity = 0.472362
 angular_vel = (-1.58059,-2.79348,-1.53495)
 linear_vel = (0.337817,-0.702074,-0.117934)
superquadric o5
 a1 = 0.0532687
 a2 = 0.0442909
 a3 = 0.0549325
 exp1 = 0.376283
 exp2 = 1.16968
 translate = (-0.300898,0.433124,1.16658)
 elasticity = 0.714847
 linear_vel = (-0.376027,0.785073,-0.179744)
polyhedron h0
 file = @DATA@/prism_seed6785_0.off
 translate = (0.11013,0.663483,1.11869)
 elasticity = 0.888007
polyhedron h1
 file = @DATA@/prism_seed6785_1.off
 translate = (0.244848,0.654321,1.51029)
 elasticity = 0.0678649
step 8
force = (-0.280516,0.273497,-1) 6.93385
step 4
max_linear = 16
