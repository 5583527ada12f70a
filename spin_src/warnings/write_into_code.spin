'' A hub write into the program's own code: buf has 4 bytes, the loop writes
'' 8, and the last four land on main's own bytecode (it follows the DAT).
DAT
buf     byte    0[4]

PUB main | i
  repeat i from 0 to 7
    buf[i] := "x"
