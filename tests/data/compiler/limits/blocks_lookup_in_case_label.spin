PUB main | x, i
  repeat
    repeat
      repeat
        repeat
          repeat
            repeat
              repeat
                repeat
                  case x
                      lookup(x: 1): x := 1
