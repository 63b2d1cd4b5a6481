-- sandbox: dofile outside the scene's folder is refused
dofile("/etc/hostname")
