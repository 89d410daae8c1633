# args: -q @
# -q hides notes; errors still show
cube box
  radius = 2
  size = (2, 2, 2)
  radius = -1
