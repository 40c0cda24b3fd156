-- h_over_dr must be in (0, 10]: 0 is refused.
domain { 0, 0, 1, 1 }
particles { dr = 0.1, h_over_dr = 0 }
scheme "ballistic"
fill { 0.1, 0.1, 0.9, 0.9 }
run { t_end = 1 }
