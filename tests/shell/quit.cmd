# quit leaves at once, with the status of what ran before (an error: 1)
sphere a
radius = -1
quit
dump
