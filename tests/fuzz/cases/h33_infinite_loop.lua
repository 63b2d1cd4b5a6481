-- nasty: an endless loop (stopped by --max-cpu with its line; the fuzz driver passes half its CPU budget)
-- fuzz-set: long
while true do end
