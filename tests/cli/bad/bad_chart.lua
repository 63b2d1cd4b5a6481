-- porelab.chart with x and y of different lengths: a clear error naming the series
porelab.chart { file = "bad.png", series = { { name = "a", x = {1, 2, 3}, y = {1, 2} } } }
