domain { 0, 0, 1, 1, periodic = "x" }
particles { dr = 0.1 }
scheme "isph-usaw"
fluid { viscosity = 1, flow_rate_control = { velocity = 1 } }
fill { 0, 0, 1, 1 }
run { t_end = 1 }
