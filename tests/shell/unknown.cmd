# Unknown commands and attributes, with did-you-mean (edit distance;
# case is a difference: commands are lower case)
strat
sphre a
Sphere a
sphere a
radus = 1
colr = (1, 2, 3)
timestep = 0.1
colision_dist = 0.1
gravty
xyzzy
frobnicate = 3
=
= 3
(1, 2, 3)
123
Help
