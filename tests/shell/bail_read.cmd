# args: -b
# -b on stdin, the error inside a read file: the rest of the read file
# and of stdin are not read
sphere a
read sub/bad.cmd
dump
