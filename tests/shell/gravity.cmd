# gravity = force (0,0,-1) 9.8: z = z0 - 4.9 t^2, vz = -9.8 t.  t = 0.5
# (4 frames of 0.125, exact in binary): z = -9.8/8 = -1.225, vz = -4.9.
time_step = 0.125
gravity
sphere g
step 4
dump
stats
