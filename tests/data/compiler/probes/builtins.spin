' Probe: built-in commands and functions
VAR
  long a, stk[20], buf[4]

PUB main | x, y
  f
  f2(1, 2)
  x := f2(3, 4)
  \f
  x := \f2(1, 2)
  cognew(f2(5, 6), @stk)
  x := cognew(f2(5, 6), @stk)
  cognew(f, @stk)
  coginit(3, f2(5, 6), @stk)
  coginit(a, f, @stk[4])
  cognew(@entry, 7)
  x := cognew(@entry, @buf)
  coginit(a, @entry, 8)
  coginit(cogid, @entry, 0)
  cogstop(x)
  x := cogid
  x := locknew
  locknew
  lockret(x)
  lockset(x)
  x := lockset(x)
  lockclr(x)
  x := lockclr(x)
  waitcnt(x)
  waitcnt(cnt + clkfreq / 1000)
  waitpeq(1, 2, 0)
  waitpne(%100, %100, 0)
  waitvid(1, 2)
  clkset(1, 2)
  clkset(clkmode, clkfreq)
  reboot
  x := chipver
  x := clkfreq
  x := clkmode
  bytemove(@buf, @stk, 3)
  wordmove(@buf, @stk, 3)
  longmove(@buf, @stk, 3)
  bytefill(@buf, 0, 16)
  wordfill(@buf, $FFFF, 8)
  longfill(@buf, -1, 4)
  x := strsize(string("hello"))
  x := strcomp(string("a"), string("b"))
  x := string("ab", 13, 10)
  x := string("ab")
  x := string("ab")
  x := lookup(a: 5, 6, 7..9)
  x := lookupz(a: 5, 6, 7..9)
  x := lookdown(a: 5, 6, 7..9)
  x := lookdownz(a: "a".."z", "0")
  x := lookup(a: 10, 20, 30, 40, 50, 60)
  y := a == lookup(x: 1, 2)
  case a
    1: y := string("one")
    other: y := string("other")
  y := string("after")

PRI f

PRI f2(p, q)
  return p + q

DAT
entry   long    0
