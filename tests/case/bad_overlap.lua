domain { 0, 0, 2, 1 }
particles { dr = 0.1 }
scheme "none"
box_wall { 0, 0, 1, 1 }
circle { centre = {0.5, 0.5}, radius = 0.2, group = "cylinder" }
fill { 0, 0, 1.5, 1, name = "everywhere" }
run { t_end = 1 }
