'' One cog drives a pin low while another holds it high: main switches the
'' LED on P5 on, then starts a cog that makes P5 an output (low) to switch
'' it off. The pins OR the cogs' outputs, so the LED stays on.
VAR
  long stack[16]

PUB main
  dira[5]~~
  outa[5]~~                                             ' LED on
  cognew(switch_off, @stack)
  waitcnt(cnt + 100_000)

PRI switch_off
  dira[5]~~                                             ' output, low: meant to switch it off
  waitcnt(cnt + 50_000)
