# SPEC 1 lexical rules: blanks, tabs, comments anywhere, = without blanks,
# vectors with blanks, number forms of strtod (no hex, inf, nan)

	 	
   # an indented comment
sphere	a   # a comment after a statement
	radius=0.5
translate=( 1 ,	2 , 3 )
linear_vel = (+1e-1, -.5, 5.)
angular_vel =(0,0,0)#comment right after
color = (0, 255, 1e2)
show a
