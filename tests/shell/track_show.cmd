# track FILE and show head|hand (SPEC 8): poses between samples, buttons
# at their sample's time, held after the last sample; a bad track line is
# an error naming the track file and its line, and plays nothing
show hand
time_step = 0.25
track track_show.trk
show head
show hand
step
show hand
step
show hand
step 3
show hand
show head
restart
show head
track track_bad.trk
show head
track no_such.trk
