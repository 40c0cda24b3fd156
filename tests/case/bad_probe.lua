-- Bad probes, refused with the line: `which` = 1 three points, 2 points = on a point probe, 3 a
-- face whose ends coincide, 4 points = 2.5, 5 a face's end outside the domain, 6 a name used
-- twice, 7 from = without to =.
param { which = 1 }
domain { 0, 0, 1, 1 }
particles { dr = 0.1 }
scheme "ballistic"
box_wall { 0, 0, 1, 1 }
fill { 0.1, 0.1, 0.9, 0.9 }
if which == 1 then probe { "three", {0.5, 0.5}, {0.6, 0.5}, {0.7, 0.5} } end
if which == 2 then probe { "point", {0.5, 0.5}, points = 3 } end
if which == 3 then probe { "same", {0.5, 0.5}, {0.5, 0.5} } end
if which == 4 then probe { "half", {0.5, 0.5}, {0.6, 0.5}, points = 2.5 } end
if which == 5 then probe { "long", {0.5, 0.5}, {0.5, 1.5} } end
if which == 6 then
  probe { "twice", {0.5, 0.5} }
  probe { "twice", {0.5, 0.6}, {0.5, 0.7} }
end
if which == 7 then probe { name = "open", from = {0.5, 0.5} } end
run { t_end = 1 }
