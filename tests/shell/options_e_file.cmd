# args: -e restart @ -e exit -e dump
# a file between -e statements; `exit` leaves at once: no dump
sphere x
dump
