-- security: package.searchpath would tell whether any file exists
print(package.searchpath("passwd", "/etc/?"))
