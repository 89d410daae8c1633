# OFF polyhedra are the convex hull of their vertices (man vroc, OFF
# FILES): a non-convex mushroom is taken as its hull; COFF's colours are
# ignored; scale stretches the vertices, one factor or one per axis.
# Checked by their fall onto the floor (gravity, no bounce): each comes to
# rest with its centre of mass (the dump's position) as high above the
# floor as its hull and scale say, plus the contact gap (under 1 mm):
#   mushroom: the hull, a frustum from the stem's 0.5 m square at z = 0 to
#     the cap's 2 m square at z = 1 under the 0.5 m cap: 0.98333 m
#     (the real, non-convex mushroom would stand at 1.16667 m)
#   big, the unit tetrahedron (COFF) scaled 2: 0.5 m
#   tall, the unit tetrahedron scaled (1,1,3): 0.75 m
gravity
default_elasticity = 0
collision_dist = 0.01
cube floor
  size = (10, 10, 0.5)
  translate = (0, 0, -0.5)
  mass = -1
polyhedron mushroom
  file = shapes/mushroom.off
  translate = (-4, 0, 1.5)
polyhedron big
  file = shapes/tetra.coff
  scale = 2
  translate = (0, 0, 1)
polyhedron tall
  file = shapes/tetra.off
  scale = (1, 1, 3)
  translate = (4, 0, 1)
show tall
scale = 0
scale = (1, 2e6, 1)
scale = (1, 1)
radius = 2
start
dump
