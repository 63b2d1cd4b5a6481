-- nasty: an endless loop (issue 13 item 5: no CPU limit yet)
-- fuzz-set: long
-- fuzz-expect: fail (issue 13 item 5: no CPU limit; killed by ulimit -t / timeout)
while true do end
