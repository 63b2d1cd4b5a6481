-- nasty: the scene returns a function
return function() end
