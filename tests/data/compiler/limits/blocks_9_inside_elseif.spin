PUB main | x
  if x
    x := 1
  elseif x
    if x
      if x
        if x
          if x
            if x
              if x
                if x
                  if x
                    x := 1
