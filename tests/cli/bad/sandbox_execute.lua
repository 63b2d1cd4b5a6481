-- sandbox: shell commands are refused
os.execute("echo should-not-run")
