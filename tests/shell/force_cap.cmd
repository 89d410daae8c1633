# force = (0,0,-1) 8 with max_linear = 2 (thesis eq. 5: once |v| reaches the
# cap it stays constant): v reaches 2 at t = 0.25, z(0.25) = -0.25; then
# z = -0.25 - 2 (t - 0.25): at t = 0.5, z = -0.75, vz = -2.  A direction of
# any length is normalised: (0,0,-5) is the same force.
time_step = 0.125
max_linear = 2
force = (0, 0, -5) 8
sphere c
step 4
dump
