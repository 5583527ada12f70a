PUB main | x, i
  if x
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
