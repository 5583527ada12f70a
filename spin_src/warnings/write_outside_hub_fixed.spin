'' The pointer is set before it is used.
VAR
  long table, count
  long data[4]

PUB main | ptr
  table := @data[1]
  ptr := table - 4
  long[ptr] := 42
  count := 1
