'' A hub write through a bad pointer: "table" holds an address that was never
'' set (0 - 4 = $FFFC), so long[ptr] lands in ROM and the write is lost.
VAR
  long table, count

PUB main | ptr
  ptr := table - 4                                      ' table should have been set to @something
  long[ptr] := 42
  count := 1
