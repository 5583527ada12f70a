'' Conformance probe: cogs share variables whose offsets take two bytes.
'' A VAR, DAT or LOC access with an offset of 128 or more reads its second
'' offset byte first and touches hub RAM 16 cycles later than one with a
'' one-byte offset.  Writers keep counting into such variables through
'' pointers (no offset); the reader reads them by name (two-byte offsets) at a
'' cycle that moves by one each pass, so it lands on every phase of the
'' writers' loops, and keeps what it saw.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long xs[32], ws[32], ds[32], stack1[24], stack2[24], done
  long pad[8], x
  word w
DAT
  dpad long 0[40]
  d    long 0
PUB main | k, t
  cognew(writer(@x, @w), @stack1)
  cognew(dat_writer(@d), @stack2)
  waitcnt(cnt + 20_000)
  repeat k from 0 to 31
    t := cnt + 3_000 + k
    waitcnt(t)
    xs[k] := x
    t := cnt + 3_000 + k * 3
    waitcnt(t)
    ws[k] := w
    t := cnt + 3_000 + k * 5
    waitcnt(t)
    ds[k] := d
  done := 1
PRI writer(px, pw) | n
  repeat until done
    long[px] := n++
    word[pw] := n
PRI dat_writer(pd) | n
  repeat until done
    long[pd] := n += 3
