PUB main | x, i
  repeat
    repeat
      repeat
        repeat
          repeat
            repeat
              repeat
                repeat
                  x := lookup(x: 1, lookup(x: 1, 2))
