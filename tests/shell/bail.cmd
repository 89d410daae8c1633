# args: -b @
# -b stops at the first error: nothing after line 5 runs
sphere a
dump
radius = -1
dump
sphere b
