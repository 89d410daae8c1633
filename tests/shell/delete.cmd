# delete NAME removes the object; unknown names are errors, with a
# suggestion among the objects
sphere ball1
sphere ball2
cube box
delete ball2
delete ball2
delete bal1
delete
dump
stats
