# Extra words after a complete statement are an error (and nothing runs)
sphere a b
start now
gravity 9.8
dump all
stats please
sphere c
  radius = 1 2
  color = (1, 2, 3) 4
step 1 2
step 1 frame
delete c d
show c c
random 2 3
help step me
quit now
dump
