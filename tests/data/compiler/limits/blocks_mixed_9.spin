PUB main | x, i
  case x
    1..3:
      repeat i from 0 to 2
        if x
          repeat 2
            case x
              1..3:
                repeat while i < 3
                  ifnot x
                    repeat
                      if x
                        x := 1
