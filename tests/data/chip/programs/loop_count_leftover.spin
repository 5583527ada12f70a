{{ What a finished "repeat n" leaves on the stack: DJNZ pops the count when it
   reaches zero without writing the 0 back, so the long below the stack pointer
   keeps 1.  A local that is never assigned reads it (locals are not cleared):
   the innermost count below lies where leftover's local does. }}
VAR
  long total, last

PUB main | x
  repeat 200
    repeat 1
      repeat 1
        repeat 1
          repeat 3
            x++
    total += leftover
  last := leftover

PRI leftover : r | garbage
  r := garbage
