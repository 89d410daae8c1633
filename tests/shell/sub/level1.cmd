# read by read_nested.cmd
sphere mid
read level2.cmd           # sub/level2.cmd, relative to this file
bogus_in_level1
