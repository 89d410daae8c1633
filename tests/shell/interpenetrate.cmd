# Objects that interpenetrate at the start are reported by pair and the
# simulation does not start (thesis 3.4.2): start and step are errors.
# Moving one away makes it start.
sphere a
sphere b
  translate = (1, 0, 0)
start
step
dump
  translate = (3, 0, 0)
step
dump
