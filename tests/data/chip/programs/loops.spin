VAR
  long n, buf[64]
  byte s[80]
PUB main | i
  bytefill(@buf, 7, 0)
  wordfill(@buf, 7, 0)
  longfill(@buf, 7, 0)
  bytemove(@buf + 40, @buf, 0)
  bytemove(@buf, @buf + 41, 0)
  wordmove(@buf + 40, @buf, 0)
  longmove(@buf + 40, @buf, 0)
  bytefill(@s, 65, 0)
  s[0] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[0] := 1
  s[1] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 1)
  wordfill(@buf, 7, 1)
  longfill(@buf, 7, 1)
  bytemove(@buf + 40, @buf, 1)
  bytemove(@buf, @buf + 41, 1)
  wordmove(@buf + 40, @buf, 1)
  longmove(@buf + 40, @buf, 1)
  bytefill(@s, 65, 1)
  s[1] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[1] := 1
  s[2] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 2)
  wordfill(@buf, 7, 2)
  longfill(@buf, 7, 2)
  bytemove(@buf + 40, @buf, 2)
  bytemove(@buf, @buf + 41, 2)
  wordmove(@buf + 40, @buf, 2)
  longmove(@buf + 40, @buf, 2)
  bytefill(@s, 65, 2)
  s[2] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[2] := 1
  s[3] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 3)
  wordfill(@buf, 7, 3)
  longfill(@buf, 7, 3)
  bytemove(@buf + 40, @buf, 3)
  bytemove(@buf, @buf + 41, 3)
  wordmove(@buf + 40, @buf, 3)
  longmove(@buf + 40, @buf, 3)
  bytefill(@s, 65, 3)
  s[3] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[3] := 1
  s[4] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 4)
  wordfill(@buf, 7, 4)
  longfill(@buf, 7, 4)
  bytemove(@buf + 40, @buf, 4)
  bytemove(@buf, @buf + 41, 4)
  wordmove(@buf + 40, @buf, 4)
  longmove(@buf + 40, @buf, 4)
  bytefill(@s, 65, 4)
  s[4] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[4] := 1
  s[5] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 5)
  wordfill(@buf, 7, 5)
  longfill(@buf, 7, 5)
  bytemove(@buf + 40, @buf, 5)
  bytemove(@buf, @buf + 41, 5)
  wordmove(@buf + 40, @buf, 5)
  longmove(@buf + 40, @buf, 5)
  bytefill(@s, 65, 5)
  s[5] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[5] := 1
  s[6] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 6)
  wordfill(@buf, 7, 6)
  longfill(@buf, 7, 6)
  bytemove(@buf + 40, @buf, 6)
  bytemove(@buf, @buf + 41, 6)
  wordmove(@buf + 40, @buf, 6)
  longmove(@buf + 40, @buf, 6)
  bytefill(@s, 65, 6)
  s[6] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[6] := 1
  s[7] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 7)
  wordfill(@buf, 7, 7)
  longfill(@buf, 7, 7)
  bytemove(@buf + 40, @buf, 7)
  bytemove(@buf, @buf + 41, 7)
  wordmove(@buf + 40, @buf, 7)
  longmove(@buf + 40, @buf, 7)
  bytefill(@s, 65, 7)
  s[7] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[7] := 1
  s[8] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 8)
  wordfill(@buf, 7, 8)
  longfill(@buf, 7, 8)
  bytemove(@buf + 40, @buf, 8)
  bytemove(@buf, @buf + 41, 8)
  wordmove(@buf + 40, @buf, 8)
  longmove(@buf + 40, @buf, 8)
  bytefill(@s, 65, 8)
  s[8] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[8] := 1
  s[9] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 9)
  wordfill(@buf, 7, 9)
  longfill(@buf, 7, 9)
  bytemove(@buf + 40, @buf, 9)
  bytemove(@buf, @buf + 41, 9)
  wordmove(@buf + 40, @buf, 9)
  longmove(@buf + 40, @buf, 9)
  bytefill(@s, 65, 9)
  s[9] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[9] := 1
  s[10] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 10)
  wordfill(@buf, 7, 10)
  longfill(@buf, 7, 10)
  bytemove(@buf + 40, @buf, 10)
  bytemove(@buf, @buf + 41, 10)
  wordmove(@buf + 40, @buf, 10)
  longmove(@buf + 40, @buf, 10)
  bytefill(@s, 65, 10)
  s[10] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[10] := 1
  s[11] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 11)
  wordfill(@buf, 7, 11)
  longfill(@buf, 7, 11)
  bytemove(@buf + 40, @buf, 11)
  bytemove(@buf, @buf + 41, 11)
  wordmove(@buf + 40, @buf, 11)
  longmove(@buf + 40, @buf, 11)
  bytefill(@s, 65, 11)
  s[11] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[11] := 1
  s[12] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 12)
  wordfill(@buf, 7, 12)
  longfill(@buf, 7, 12)
  bytemove(@buf + 40, @buf, 12)
  bytemove(@buf, @buf + 41, 12)
  wordmove(@buf + 40, @buf, 12)
  longmove(@buf + 40, @buf, 12)
  bytefill(@s, 65, 12)
  s[12] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[12] := 1
  s[13] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 13)
  wordfill(@buf, 7, 13)
  longfill(@buf, 7, 13)
  bytemove(@buf + 40, @buf, 13)
  bytemove(@buf, @buf + 41, 13)
  wordmove(@buf + 40, @buf, 13)
  longmove(@buf + 40, @buf, 13)
  bytefill(@s, 65, 13)
  s[13] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[13] := 1
  s[14] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 14)
  wordfill(@buf, 7, 14)
  longfill(@buf, 7, 14)
  bytemove(@buf + 40, @buf, 14)
  bytemove(@buf, @buf + 41, 14)
  wordmove(@buf + 40, @buf, 14)
  longmove(@buf + 40, @buf, 14)
  bytefill(@s, 65, 14)
  s[14] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[14] := 1
  s[15] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 15)
  wordfill(@buf, 7, 15)
  longfill(@buf, 7, 15)
  bytemove(@buf + 40, @buf, 15)
  bytemove(@buf, @buf + 41, 15)
  wordmove(@buf + 40, @buf, 15)
  longmove(@buf + 40, @buf, 15)
  bytefill(@s, 65, 15)
  s[15] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[15] := 1
  s[16] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 16)
  wordfill(@buf, 7, 16)
  longfill(@buf, 7, 16)
  bytemove(@buf + 40, @buf, 16)
  bytemove(@buf, @buf + 41, 16)
  wordmove(@buf + 40, @buf, 16)
  longmove(@buf + 40, @buf, 16)
  bytefill(@s, 65, 16)
  s[16] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[16] := 1
  s[17] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 17)
  wordfill(@buf, 7, 17)
  longfill(@buf, 7, 17)
  bytemove(@buf + 40, @buf, 17)
  bytemove(@buf, @buf + 41, 17)
  wordmove(@buf + 40, @buf, 17)
  longmove(@buf + 40, @buf, 17)
  bytefill(@s, 65, 17)
  s[17] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[17] := 1
  s[18] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 18)
  wordfill(@buf, 7, 18)
  longfill(@buf, 7, 18)
  bytemove(@buf + 40, @buf, 18)
  bytemove(@buf, @buf + 41, 18)
  wordmove(@buf + 40, @buf, 18)
  longmove(@buf + 40, @buf, 18)
  bytefill(@s, 65, 18)
  s[18] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[18] := 1
  s[19] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 19)
  wordfill(@buf, 7, 19)
  longfill(@buf, 7, 19)
  bytemove(@buf + 40, @buf, 19)
  bytemove(@buf, @buf + 41, 19)
  wordmove(@buf + 40, @buf, 19)
  longmove(@buf + 40, @buf, 19)
  bytefill(@s, 65, 19)
  s[19] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[19] := 1
  s[20] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 20)
  wordfill(@buf, 7, 20)
  longfill(@buf, 7, 20)
  bytemove(@buf + 40, @buf, 20)
  bytemove(@buf, @buf + 41, 20)
  wordmove(@buf + 40, @buf, 20)
  longmove(@buf + 40, @buf, 20)
  bytefill(@s, 65, 20)
  s[20] := 0
  n := strsize(@s)
  n := strcomp(@s, @s)
  s[20] := 1
  s[21] := 0
  n := strcomp(@s, @s + 40)
  bytefill(@buf, 7, 25)
  bytemove(@buf + 3, @buf, 12)
  bytefill(@buf, 7, 63)
  bytemove(@buf + 3, @buf, 31)
  bytefill(@buf, 7, 64)
  bytemove(@buf + 3, @buf, 32)
  bytefill(@buf, 7, 250)
  bytemove(@buf + 3, @buf, 125)
