domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme "none"
wall { {0, 0} }
fill { 0, 0, 1, 1 }
run { t_end = 1 }
