# args: @
# A file that reads itself, directly or through another, is an error, not a
# stack overflow; reading goes on after it
sphere a
read read_self.cmd
read sub/cycle.cmd
read sub
read
dump
