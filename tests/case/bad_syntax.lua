-- a Lua error on line 3
param { dr = 0.1 }
domain { 0, 0, 1, 1 
