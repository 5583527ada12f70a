PUB main | x, i
  repeat i from 1 to 2
    repeat i from 1 to 2
      repeat i from 1 to 2
        repeat i from 1 to 2
          repeat i from 1 to 2
            repeat i from 1 to 2
              repeat i from 1 to 2
                repeat i from 1 to 2
                  repeat i from 1 to 2
                    repeat i from 1 to 2
                      x := 1
