VAR
  long n, v
PUB main | i
  n := outa
  outa := outa | 0
  outa := 0
  n := outa := 0
  outa += 1
  outa~
  outa[3] := 1
  n := outa[3]
  outa[3]~~
  n := outa[3]++
  outa[7..4] := 5
  outa[4..7] := 5
  n := outa[7..4]
  n := outa[4..7]
  outa[7..4] += 3
  n := outa[4..7] := 9
  outa[7..4]--
  outa := 0
  n := dira
  dira := dira | 0
  dira := 0
  n := dira := 0
  dira += 1
  dira~
  dira[3] := 1
  n := dira[3]
  dira[3]~~
  n := dira[3]++
  dira[7..4] := 5
  dira[4..7] := 5
  n := dira[7..4]
  n := dira[4..7]
  dira[7..4] += 3
  n := dira[4..7] := 9
  dira[7..4]--
  dira := 0
  n := ina
  n := cnt
  n := par
  n := ctra
  ctra := ctra | 0
  ctra := 0
  n := ctra := 0
  ctra += 1
  ctra~
  ctra[3] := 1
  n := ctra[3]
  ctra[3]~~
  n := ctra[3]++
  ctra[7..4] := 5
  ctra[4..7] := 5
  n := ctra[7..4]
  n := ctra[4..7]
  ctra[7..4] += 3
  n := ctra[4..7] := 9
  ctra[7..4]--
  ctra := 0
  n := frqa
  frqa := frqa | 0
  frqa := 0
  n := frqa := 0
  frqa += 1
  frqa~
  frqa[3] := 1
  n := frqa[3]
  frqa[3]~~
  n := frqa[3]++
  frqa[7..4] := 5
  frqa[4..7] := 5
  n := frqa[7..4]
  n := frqa[4..7]
  frqa[7..4] += 3
  n := frqa[4..7] := 9
  frqa[7..4]--
  frqa := 0
  n := phsa
  phsa := phsa | 0
  phsa := 0
  n := phsa := 0
  phsa += 1
  phsa~
  phsa[3] := 1
  n := phsa[3]
  phsa[3]~~
  n := phsa[3]++
  phsa[7..4] := 5
  phsa[4..7] := 5
  n := phsa[7..4]
  n := phsa[4..7]
  phsa[7..4] += 3
  n := phsa[4..7] := 9
  phsa[7..4]--
  phsa := 0
  n := vcfg
  vcfg := vcfg | 0
  vcfg := 0
  n := vcfg := 0
  vcfg += 1
  vcfg~
  vcfg[3] := 1
  n := vcfg[3]
  vcfg[3]~~
  n := vcfg[3]++
  vcfg[7..4] := 5
  vcfg[4..7] := 5
  n := vcfg[7..4]
  n := vcfg[4..7]
  vcfg[7..4] += 3
  n := vcfg[4..7] := 9
  vcfg[7..4]--
  vcfg := 0
  n := vscl
  vscl := vscl | 0
  vscl := 0
  n := vscl := 0
  vscl += 1
  vscl~
  vscl[3] := 1
  n := vscl[3]
  vscl[3]~~
  n := vscl[3]++
  vscl[7..4] := 5
  vscl[4..7] := 5
  n := vscl[7..4]
  n := vscl[4..7]
  vscl[7..4] += 3
  n := vscl[4..7] := 9
  vscl[7..4]--
  vscl := 0
  n := outb
  outb := outb | 0
  outb := 0
  n := outb := 0
  outb += 1
  outb~
  outb[3] := 1
  n := outb[3]
  outb[3]~~
  n := outb[3]++
  outb[7..4] := 5
  outb[4..7] := 5
  n := outb[7..4]
  n := outb[4..7]
  outb[7..4] += 3
  n := outb[4..7] := 9
  outb[7..4]--
  outb := 0
  n := dirb
  dirb := dirb | 0
  dirb := 0
  n := dirb := 0
  dirb += 1
  dirb~
  dirb[3] := 1
  n := dirb[3]
  dirb[3]~~
  n := dirb[3]++
  dirb[7..4] := 5
  dirb[4..7] := 5
  n := dirb[7..4]
  n := dirb[4..7]
  dirb[7..4] += 3
  n := dirb[4..7] := 9
  dirb[7..4]--
  dirb := 0
  n := spr[0]
  n := spr[1]
  n := spr[2]
  n := spr[3]
  n := spr[4]
  n := spr[5]
  n := spr[6]
  n := spr[7]
  n := spr[8]
  n := spr[9]
  n := spr[10]
  n := spr[11]
  n := spr[12]
  n := spr[13]
  n := spr[14]
  n := spr[15]
  spr[4] := 0
  spr[4] += 2
  n := spr[4]++
  spr[4] := 0
  spr[5] := 0
  spr[5] += 2
  n := spr[5]++
  spr[5] := 0
  spr[6] := 0
  spr[6] += 2
  n := spr[6]++
  spr[6] := 0
  spr[7] := 0
  spr[7] += 2
  n := spr[7]++
  spr[7] := 0
  spr[8] := 0
  spr[8] += 2
  n := spr[8]++
  spr[8] := 0
  spr[10] := 0
  spr[10] += 2
  n := spr[10]++
  spr[10] := 0
  spr[14] := 0
  spr[14] += 2
  n := spr[14]++
  spr[14] := 0
  spr[15] := 0
  spr[15] += 2
  n := spr[15]++
  spr[15] := 0
  n := cogid
  n := outa[3] := 1
  n := dira[2] := 0
  outa[5]~
  n := outa[5]~~
  n := outa[6]--
  outa[4] += 1
  n := outa[2] ^= 1
  repeat outa from 0 to 3
    n++
  repeat outa from 0 to 12 step 4
    n++
  outa := 0
