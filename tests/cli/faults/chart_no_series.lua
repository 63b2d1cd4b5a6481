-- porelab.chart with an empty series list: the count is shown (it printed "invalid option
-- '%lld' to 'lua_pushfstring'").
porelab.chart { file = "bad.png", series = {} }
