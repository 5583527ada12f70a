DAT
        org $123
lab     long 0
        org $1EE
lab_ret long 0
        org 0
        mov $000, $1FF
        add $000, #$000
        jmp #$000
        mov $001, $1FE
        add $001, #$001
        jmp #$001
        mov $002, $1FD
        add $002, #$002
        jmp #$002
        mov $055, $1AA
        add $055, #$055
        jmp #$055
        mov $0AA, $155
        add $0AA, #$0AA
        jmp #$0AA
        mov $100, $0FF
        add $100, #$100
        jmp #$100
        mov $155, $0AA
        add $155, #$155
        jmp #$155
        mov $1AA, $055
        add $1AA, #$1AA
        jmp #$1AA
        mov $1EF, $010
        add $1EF, #$1EF
        jmp #$1EF
        mov $1FF, $000
        add $1FF, #$1FF
        jmp #$1FF
        mov PAR, par
        or PAR, #496
        cogid PAR
        mov CNT, cnt
        or CNT, #497
        cogid CNT
        mov INA, ina
        or INA, #498
        cogid INA
        mov INB, inb
        or INB, #499
        cogid INB
        mov OUTA, outa
        or OUTA, #500
        cogid OUTA
        mov OUTB, outb
        or OUTB, #501
        cogid OUTB
        mov DIRA, dira
        or DIRA, #502
        cogid DIRA
        mov DIRB, dirb
        or DIRB, #503
        cogid DIRB
        mov CTRA, ctra
        or CTRA, #504
        cogid CTRA
        mov CTRB, ctrb
        or CTRB, #505
        cogid CTRB
        mov FRQA, frqa
        or FRQA, #506
        cogid FRQA
        mov FRQB, frqb
        or FRQB, #507
        cogid FRQB
        mov PHSA, phsa
        or PHSA, #508
        cogid PHSA
        mov PHSB, phsb
        or PHSB, #509
        cogid PHSB
        mov VCFG, vcfg
        or VCFG, #510
        cogid VCFG
        mov VSCL, vscl
        or VSCL, #511
        cogid VSCL
        mov $005, #-1
        mov -1, $005
        jmp #-1
        djnz $005, #-1
        cogid -1
        mov $005, #-2
        mov -2, $005
        jmp #-2
        djnz $005, #-2
        cogid -2
        mov $005, #-$1FF
        mov -$1FF, $005
        jmp #-$1FF
        djnz $005, #-$1FF
        cogid -$1FF
        mov $005, #-$200
        mov -$200, $005
        jmp #-$200
        djnz $005, #-$200
        cogid -$200
        mov $005, #-$12345
        mov -$12345, $005
        jmp #-$12345
        djnz $005, #-$12345
        cogid -$12345
        if_never mov $005, #$003

PUB main
