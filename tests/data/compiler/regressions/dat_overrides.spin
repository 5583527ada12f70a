' Regression: a DAT size override holds for the rest of the line; a float after "long" is allowed
' (found by the program generator)
PUB main | x
  x := b
DAT
a           byte $01, word $0302, long $07060504, $08
            byte 1, word 2, 3, long 4, 5
            word 1, long 2[2], 3
            byte 1, long 2, 1.5
b
            long 7
