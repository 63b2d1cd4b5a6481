-- sandbox: os.getenv is refused unless --trust
print("HOME is " .. tostring(os.getenv("HOME")))
