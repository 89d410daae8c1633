# args: -e gravity - -e dump -e bogus
# -e statements and `-` (this script, the standard input) run in the order
# given: gravity before it, the dump and an error (-e:3) after it
sphere b
  translate = (0, 0, 1)
step 2
