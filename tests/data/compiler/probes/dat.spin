' Probe: DAT data layout (alignment, size overrides, counts, strings, labels)
PUB main | x
  x := @d1 + d2 + @d3 + d4 + @l5 + l5 + table[2] + @text
  x := constant(d4 - d2)
  x := constant(@d3)
  x := word[@d2][1]

DAT
        byte    1
d1
        long    2
d2      byte    3
d3
d4      word    5
l5      long    6
table   long    1, 2, 3, 4
text    byte    "Hello", 13, 0
mixed   byte    1, word $1234, long $5678
count   long    7[3]
        byte    256, -1, $1FF
        word    65536, -1
wstr    word    "AB"
flt     long    1.5, -2.5, 1e3
rep     byte    3[2], 4
addrs   word    @d1, @table
empty   long
        byte    9
