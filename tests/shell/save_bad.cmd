# bad saved files: file:line errors, nothing crashes, good lines are taken
read save_bad.vroc
dump
show head
show hand
save no/such/folder/x.vroc
step 1
state clock t=1 frames=1 t_base=0 frames_base=0 instant=0 instant_t=-inf settings_due=0
