-- No walls, no periodic axis: the fluid could leave the domain on every side.
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme "ballistic"
fill { 0.3, 0.3, 0.7, 0.7 }
run { t_end = 1 }
