-- security: link.png in the output folder is a dangling symbolic link to a file outside it
porelab.chart { file = "link.png", series = { { x = { 0, 1 }, y = { 0, 1 } } } }
