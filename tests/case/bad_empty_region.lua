domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme "none"
box_wall { 0, 0, 1, 1 }
fill { 0.41, 0.41, 0.44, 0.44, name = "speck" }
run { t_end = 1 }
