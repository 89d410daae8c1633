# Every object that cannot be built is named, not only the first (two
# polyhedra without a file), at each step that tries to start; and a
# start that fails places nothing, so the speed cap's cut of the ball's
# 20 m/s to max_linear = 8 is counted once (clamps=1, not once a try),
# and the ball keeps 8 m/s: energy = 1/2 * 1 kg * 8^2 = 32 J.
max_linear = 8
sphere fast
linear_vel = (20, 0, 0)
polyhedron h0
polyhedron h1
step 1
step 1
delete h0
delete h1
step 1
stats
