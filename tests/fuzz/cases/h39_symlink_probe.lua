-- nasty: os.remove/rename are sandboxed
os.rename('out', '../moved')
os.remove('../scene')
