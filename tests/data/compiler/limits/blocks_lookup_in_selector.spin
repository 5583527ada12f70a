PUB main | x, i
  repeat
    repeat
      repeat
        repeat
          repeat
            repeat
              repeat
                repeat
                  case lookup(x: 1, 2)
                    1..3:
                      x := 1
