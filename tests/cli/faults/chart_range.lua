-- porelab.chart with xrange {2, 1}: the message shows the numbers (it printed
-- "invalid option '%g' to 'lua_pushfstring'").
porelab.chart { file = "bad.png", xrange = { 2, 1 },
                series = { { name = "a", x = { 1, 2 }, y = { 1, 2 } } } }
