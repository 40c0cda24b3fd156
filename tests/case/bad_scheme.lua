domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme "isph-magic"
fill { 0.1, 0.1, 0.9, 0.9 }
run { t_end = 1 }
