'' Starts a PASM cog that makes P0 an output and loops.
VAR
  long id
PUB main
  id := cognew(@entry, 0)
DAT
        org 0
entry   mov dira, #1
        jmp #entry
