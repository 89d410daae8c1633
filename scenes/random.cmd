# random.cmd — thesis 5.6 "Randomized Objects": N objects flying in a room.
#
# `random N` adds N dynamic objects r0, r1, ... (alternately spheres of
# radius 0.2 m and cubes of half-size 0.15 m, 1 kg, elasticity 1) at random
# places in the room, with random orientations, speeds up to 4 m/s and spins
# up to 2 rad/s (the draw is fixed by `seed`: the same scene every run).
# All of them are dynamic, so every pair counts: N(N-1)/2 pairs among them
# (thesis table 5.6: 20 objects 190 pairs ... 100 objects 4950 pairs), plus
# 6N with the room's six static walls.  With no gravity and no energy lost
# (e = 1 everywhere) they keep flying and colliding as long as you let them,
# at a rate roughly uniform over time: the thesis's point of this scene.
#
#   with N = 40: objects 46 (40 dynamic + 6 walls), pairs 780 + 240 = 1020
#
# Change N (and `room`) on the `random` line for bigger runs; 1000 objects
# fit in a 10 m room (0.5 M pairs: slow, a few frames a second).
# max_linear and max_angular are far above anything a collision produces,
# so no clamp takes energy out; `stats` energy stays put.
#
# Run:   vroc scenes/random.cmd            (runs max_frames = 600 frames: 30 s)
# View:  printf 'frames = /tmp/random\nread scenes/random.cmd\n' | vroc
#        tools/contact-sheet /tmp/random random.png

time_step = 0.05         # 20 frames per simulated second
collision_dist = 0.01
max_linear = 16
max_angular = 100
seed = 1993

eye = (-4.6, -4.6, 9.6)
look = (0.5, 0.5, 3.5)
fov = 80                 # the eye is inside the room, in a top corner

room = 10                # a closed 10 m room of six 0.5 m walls, floor at z = 0
random 40

start                    # batch: max_frames (600 frames); nothing ever rests
