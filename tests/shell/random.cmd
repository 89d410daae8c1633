# random N adds N dynamic objects r0, r1, ... (numbering continues across
# calls, restarts after restart); room = s adds six static walls:
# r0..r2 exist and r3 does not; with the room, 4 dynamic objects and 6
# walls: 6 static objects stay after deleting r0..r3.  (Positions and
# velocities are random draws, not checked here.)
random 2
random 1
random 0
random 10001
random
delete r0
delete r1
delete r2
delete r3
stats
restart
room = 20
random 4
delete r0
delete r1
delete r2
delete r3
stats
