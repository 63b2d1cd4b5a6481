-- bad input: a file name with a newline is refused (it breaks every listing that shows it)
local f = io.open("frames\nfake.txt", "w")
