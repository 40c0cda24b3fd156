-- run { t_end } is what runs, also when the case declares a parameter t_end: `which` = 1 runs
-- three times the parameter, 2 gives a negative end time, 3 gives no end time.
param { t_end = 0.1, which = 1 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme "ballistic"
box_wall { 0, 0, 1, 1 }
fill { 0.1, 0.1, 0.9, 0.9 }
if which == 1 then
  run { t_end = 3 * t_end }
elseif which == 2 then
  run { t_end = -1 }
else
  run { output_every = 0.1 }
end
