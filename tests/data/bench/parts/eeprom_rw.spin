'' eeprom_rw.spin: a page write, ACK polling and a random read of the boot EEPROM (24LC256 on P28/P29),
'' with an I2C master written in Spin: SCL driven, SDA open drain (DIRA pulls it low, the pull-up lifts it).
'' Results in VAR: acks (bytes acknowledged), polls (control bytes sent until the write cycle ended),
'' readback[0..4] (the bytes read back).

CON
  _clkmode = xtal1 + pll16x
  _xinfreq = 5_000_000
  SCL = 28
  SDA = 29
  EEPROM = $A0

VAR
  long acks, polls
  byte readback[8]

PUB main | i
  outa[SCL] := 1
  dira[SCL] := 1
  dira[SDA] := 0
  start
  send(EEPROM)
  send($7F)
  send($00)
  repeat i from 0 to 4
    send(i * 3 + 7)
  stop
  repeat                                                ' ACK polling: the write cycle takes 5 ms
    start
    polls++
  until write(EEPROM)
  send($7F)                                             ' random read: the address, then a repeated START
  send($00)
  start
  send(EEPROM | 1)
  repeat i from 0 to 4
    readback[i] := read(i < 4)
  stop

PRI send(b)
  if write(b)
    acks++

PRI start
  dira[SDA] := 0
  outa[SCL] := 1
  dira[SDA] := 1                                        ' SDA falls while SCL is high
  outa[SCL] := 0

PRI stop
  dira[SDA] := 1
  outa[SCL] := 1
  dira[SDA] := 0                                        ' SDA rises while SCL is high

PRI write(b) : ack | i
  repeat i from 7 to 0
    dira[SDA] := (b >> i & 1) ^ 1
    outa[SCL] := 1
    outa[SCL] := 0
  dira[SDA] := 0
  outa[SCL] := 1
  ack := ina[SDA] == 0
  outa[SCL] := 0

PRI read(more) : b
  dira[SDA] := 0
  repeat 8
    outa[SCL] := 1
    b := (b << 1) | ina[SDA]
    outa[SCL] := 0
  dira[SDA] := more & 1
  outa[SCL] := 1
  outa[SCL] := 0
  dira[SDA] := 0
