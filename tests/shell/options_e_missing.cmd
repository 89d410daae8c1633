# args: -q -e
