-- The clustering distance was cluster_spacing, in units of dr, until cluster_h (in smoothing
-- lengths h) replaced it: a script that still sets it is refused with the equivalent value
-- (tests/case.cmake).
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme "none"
fluid { density = 1000 }
box_wall { 0, 0, 1, 1 }
fill { 0, 0, 1, 1 }
run { t_end = 1, checks = { cluster_spacing = 0.25 } }
