PUB main | x, i
  repeat
    repeat
      repeat
        repeat
          repeat
            repeat
              repeat
                repeat
                  repeat i from lookup(x: 1, 2) to 3
                    x := 1
