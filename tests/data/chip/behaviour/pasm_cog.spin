'' Starts a PASM cog (not emulated): the run must say so.
VAR
  long id
PUB main
  id := cognew(@entry, 0)
DAT
        org 0
entry   mov dira, #1
        jmp #entry
