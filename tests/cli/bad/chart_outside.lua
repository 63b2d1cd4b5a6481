-- porelab.chart may not write outside the output folder (sandbox)
porelab.chart { file = "../../escape.png", series = { { x = {1, 2}, y = {1, 2} } } }
