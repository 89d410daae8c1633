# read by read_self.cmd: reads it again
read ../read_self.cmd
