# the tool panel (SPEC 8, man vroc TOOL PANEL): off by default; its
# controls' centres in world coordinates, the sliders' knobs where their
# settings put them; `panel` is no object name
show panel
panel = 1
show panel
time_step = 1
collision_dist = 0.001
show panel
time_step = 5
collision_dist = 0.0447213595499958
show panel
sphere panel
panel = 2
select = 1
panel = 0
show panel
