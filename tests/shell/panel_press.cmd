# The tool panel worked by a track file's hand, end to end (SPEC 8, man
# vroc TOOL PANEL): the trigger pulled on the stop button at 0.5 s stops
# a running `start` after the frame it was pressed in (frames = 6, time
# 0.6), where a falling ball alone would run to max_frames; the same
# press with panel = 0 does nothing (the run goes on to max_frames = 20)
panel = 1
time_step = 0.1
max_frames = 20
sphere ball
translate = (0,0,5)
track panel_press.trk
start
stats
restart
panel = 0
time_step = 0.1
max_frames = 20
sphere ball
translate = (0,0,5)
track panel_press.trk
start
stats
