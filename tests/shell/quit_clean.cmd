# quit after no error: status 0, nothing after it runs
sphere a
quit
radius = -1
