' Probe: objects, object arrays, calls, obj#CONST, shared and nested children, VAR offsets
CON
  N = a#COUNT + 1

OBJ
  a     : "child_a"
  b[2]  : "child_b"
  c     : "child_a"
  d     : "child_c.spin"

VAR
  long top
  byte flag

PUB main | i
  a.start(1)
  b[1].work
  b[i].work
  top := c.value + b[0].value
  top := a#COUNT * N
  top := d.value(top, i)
  \a.start(2)
  top := \b[1].value
  repeat i from 0 to 1
    b[i].work
