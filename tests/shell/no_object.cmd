# An attribute with no object selected is an error (nothing is applied);
# delete of the selected object and restart unselect it.
radius = 1
translate = (1, 2, 3)
sphere a
  radius = 2
delete a
  radius = 3
sphere b
restart
  color = (1, 2, 3)
dump
