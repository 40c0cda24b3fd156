-- An unknown scheme: `which` = 1 a name like no scheme (the list), 2 a misspelt one (the nearest).
param { which = 1 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme(which == 1 and "isph-magic" or "wcsph-usw")
fill { 0.1, 0.1, 0.9, 0.9 }
run { t_end = 1 }
