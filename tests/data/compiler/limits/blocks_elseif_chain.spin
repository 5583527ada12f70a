PUB main | x
  if x
    x := 1
  elseif x
    x := 1
  elseif x
    x := 1
  elseif x
    x := 1
  elseif x
    x := 1
  elseif x
    x := 1
  elseif x
    x := 1
  elseif x
    x := 1
  elseif x
    x := 1
  elseif x
    x := 1
  elseif x
    x := 1
  elseif x
    x := 1
  elseif x
    x := 1
  elseif x
    x := 1
  elseif x
    x := 1
  elseif x
    x := 1
  else
    x := 2
