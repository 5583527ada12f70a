PUB main | x, i
  repeat
    repeat
      repeat
        repeat
          repeat
            repeat
              repeat
                repeat
                  repeat lookup(x: 1, 2)
                    x := 1
