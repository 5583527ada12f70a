'' A 1 kHz NCO on P4 for as long as the run goes, while the cog toggles P5 about every millisecond.
'' (spinemu counter tests: tests/chip/test_listen_counters.py, tests/benchmarks/bench_listen.py)
CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
PUB main
  dira[4] := 1
  frqa := 53_687                        ' 2**32 * 1_000 / 80_000_000
  ctra := %00100 << 26 | 4
  dira[5] := 1
  repeat
    !outa[5]
    waitcnt(cnt + 80_000)
