# a name is one object: `cube ball` after `sphere ball` selects the sphere
# and says so (a note; -q hides it); its attributes stay a sphere's
sphere ball
  radius = 0.5
cube ball
  size = (1, 1, 1)
sphere ball
show ball
exit
dump
