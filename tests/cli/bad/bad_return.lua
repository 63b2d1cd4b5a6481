-- bad input: the scene returns something that is not a world
return 42
