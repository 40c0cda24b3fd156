param { dr = 0.1 }
domain { 0, 0, 1, 1 }
particles { dr = dr }
scheme "none"
fill { 0, 0, 1, 1 }
run { t_end = 0.1 }
render { field = "p", range = {1, 0} }
