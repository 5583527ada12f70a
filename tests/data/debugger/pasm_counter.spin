'' The debugger's PASM test program: cog 1 counts to 5 through a subroutine,
'' writes each count to the VAR long 'count', toggles P0, then stops itself.
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
VAR
  long count
PUB main
  cognew(@entry, @count)
  repeat until count == 5
  waitcnt(cnt + 2_000)
DAT
        org     0
entry   mov     addr, par
        mov     n, #0
        or      dira, #1
loop    call    #bump
        wrlong  n, addr
        xor     outa, #1
        cmp     n, #5           wz
  if_nz jmp     #loop
        cogid   n
        cogstop n
bump    add     n, #1
bump_ret ret
addr    long    0
n       long    0
spare   res     2
