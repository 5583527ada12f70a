PUB main | x
  if x
    x := 1
  else
    if x
      if x
        if x
          if x
            if x
              if x
                if x
                  if x
                    if x
                      x := 1
