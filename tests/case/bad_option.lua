domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme { "none", shifting = 0.7 }
box_wall { 0, 0, 1, 1 }
fill { 0, 0, 1, 1 }
run { t_end = 1 }
