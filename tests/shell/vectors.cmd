# vectors: (x,y,z), blanks allowed; every malformation is an error that
# changes nothing
sphere a
  translate = (1, 2, 3)
  translate = 1, 2, 3
  translate = (1, 2, 3
  translate = (1, 2)
  translate = (1, 2, 3, 4)
  translate = (1 2 3)
  translate = (1, , 3)
  translate = ()
  translate = (1, 2, nan)
  translate = (1, 2, 1e999)
  translate =
  translate (1, 2, 3)
  color = (256, 0, 0)
  color = (0, -1, 0)
  color = (0, 0, 0.5)
  rotate = (0, 0, 0) 1
  rotate = (0, 0, 1)
  rotate = (0, 0, 1) x
  rotate = (0, 0, 1) 1 2
  size = (1, 1, 1)
resolution = (15, 512)
resolution = (640, 8193)
resolution = (640.5, 512)
resolution = (640, 512, 3)
up = (0, 0, 0)
force = (0, 0, 0) 9.8
force = (0, 0, -1) -1
force = (0, 0, -1)
show a
