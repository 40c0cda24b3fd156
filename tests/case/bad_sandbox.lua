param { dr = 0.1 }
local f = io.open("/etc/passwd")
