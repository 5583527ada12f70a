PUB main | x, i
  repeat
    repeat
      repeat
        repeat
          repeat
            repeat
              repeat
                repeat
                  repeat
                    repeat
                      x := 1
