# SPEC 1.1: a freshly created object has the thesis's defaults; dump shows
# it at the origin, unrotated, at rest velocity, time 0
sphere s
cube c
superquadric q
dump
polyhedron p             # no file yet: shown, not dumped
show s
show c
show q
show p
