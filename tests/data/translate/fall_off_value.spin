'' A method that falls off its end returns RESULT, 0 unless set, even when
'' it returns a value elsewhere or never names RESULT at all.
OBJ
  kid : "fall_off_child"
VAR
  long flag, r1, r2, r3, r4, r5
PUB main
  r1 := size                            ' falls off: 0
  r2 := proc + 1                        ' a procedure's value: 0 + 1
  r3 := \proc + kid.stop                ' through a trap, in a child: 0
  flag := 1
  r4 := size                            ' 512 now
  r5 := size + r1 + r2 + r3             ' 513
  dira[0..9]~~
  outa[0..9] := r5 + r4
PRI size
  if flag
    return 512
PRI proc
  flag := 0
