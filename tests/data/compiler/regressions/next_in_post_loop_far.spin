' Regression: OpenSpin's "next" in "repeat ... while/until" goes to the top of the loop until
' the test is met in the loop's first compile: a next that is exactly 63 bytes from the test
' is short when it is within reach of the top (near), long when it is not (far; found by the
' program generator)
PUB far | a, l5, l6, l7, l8, l9[2]
  repeat
    ifnot (l9[($7CB9B93A) & 1]) #> LOOKUP(($00080000001) & 7: "bd", 0, l9[(l8) & 1], $3..$0_006_, "ef")
      a := 123456
      if (d0 - (trunc((float(11_376) - 12345.879)) / ((-"z") >> 1 | 1)) #> 3)
        next
    l6 := 0
    repeat until (++l6 > 3) OR ((l9[(1_27) & 1] := 71))
     ~~l9[(l9[%1]~) & 1]
    a := 123456
    a := 123456
    a := 123456
    a := 123456
    a := 123456
    a := 123456
    a := 100
  while l5++ < 2
PUB near | a, l5, l6, l7, l8, l9[2]
  repeat
    ifnot (l9[($7CB9B93A) & 1]) #> LOOKUP(($00080000001) & 7: "bd", 0, l9[(l8) & 1], $3..$0_006_, "ef")
      a := 1000
      if (d0 - (trunc((float(11_376) - 12345.879)) / ((-"z") >> 1 | 1)) #> 3)
        next
    l6 := 0
    repeat until (++l6 > 3) OR ((l9[(1_27) & 1] := 71))
     ~~l9[(l9[%1]~) & 1]
    a := 123456
    a := 123456
    a := 123456
    a := 123456
    a := 123456
    a := 123456
    a := 100
  while l5++ < 2
DAT
d0
d1        word 5, word 3555, 8318, 50086
d2 long @d0, @d1
