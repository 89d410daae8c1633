# read nests; relative paths are relative to the reading file; an error
# inside a read file names the chain of reads
sphere top
read sub/level1.cmd
show deep
dump
