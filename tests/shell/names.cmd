# Names: [A-Za-z_][A-Za-z0-9_.-]*, at most 63 bytes; a reused name selects
# the original object whatever the type word
sphere 1ball
sphere ball!
sphere -x
sphere a:b
sphere
sphere abcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijk
sphere abcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijkl
sphere _ok.name-2
sphere Ball
cube ball
cube _ok.name-2
  radius = 0.5
  size = (2, 2, 2)
dump
show _ok.name-2
