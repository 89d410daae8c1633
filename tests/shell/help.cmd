# help lists every command from the table; help NAME describes one
help
help radius
help step
help sphere
help distribution
help radus
help nothing_like_it
