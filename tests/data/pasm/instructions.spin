DAT
        org $123
lab     long 0
        org $1EE
lab_ret long 0
        org 0
        wrbyte $0A5, $15A
        wrbyte $0A5, $15A wz
        wrbyte $0A5, $15A wc
        wrbyte $0A5, $15A wz, wc
        wrbyte $15A, #$0A5
        wrbyte $15A, #$0A5 wz
        wrbyte $15A, #$0A5 wc
        wrbyte $15A, #$0A5 wz, wc
        rdbyte $0A5, $15A
        rdbyte $0A5, $15A wz
        rdbyte $0A5, $15A wc
        rdbyte $0A5, $15A wz, wc
        rdbyte $15A, #$0A5
        rdbyte $15A, #$0A5 wz
        rdbyte $15A, #$0A5 wc
        rdbyte $15A, #$0A5 wz, wc
        wrword $0A5, $15A
        wrword $0A5, $15A wz
        wrword $0A5, $15A wc
        wrword $0A5, $15A wz, wc
        wrword $15A, #$0A5
        wrword $15A, #$0A5 wz
        wrword $15A, #$0A5 wc
        wrword $15A, #$0A5 wz, wc
        rdword $0A5, $15A
        rdword $0A5, $15A wz
        rdword $0A5, $15A wc
        rdword $0A5, $15A wz, wc
        rdword $15A, #$0A5
        rdword $15A, #$0A5 wz
        rdword $15A, #$0A5 wc
        rdword $15A, #$0A5 wz, wc
        wrlong $0A5, $15A
        wrlong $0A5, $15A wz
        wrlong $0A5, $15A wc
        wrlong $0A5, $15A wz, wc
        wrlong $15A, #$0A5
        wrlong $15A, #$0A5 wz
        wrlong $15A, #$0A5 wc
        wrlong $15A, #$0A5 wz, wc
        rdlong $0A5, $15A
        rdlong $0A5, $15A wz
        rdlong $0A5, $15A wc
        rdlong $0A5, $15A wz, wc
        rdlong $15A, #$0A5
        rdlong $15A, #$0A5 wz
        rdlong $15A, #$0A5 wc
        rdlong $15A, #$0A5 wz, wc
        hubop $0A5, $15A
        hubop $0A5, $15A wz
        hubop $0A5, $15A wc
        hubop $0A5, $15A wr
        hubop $0A5, $15A nr
        hubop $0A5, $15A wz, wc
        hubop $0A5, $15A wz, wr
        hubop $0A5, $15A wz, nr
        hubop $0A5, $15A wc, wr
        hubop $0A5, $15A wc, nr
        hubop $0A5, $15A wr, nr
        hubop $0A5, $15A wz, wc, wr
        hubop $0A5, $15A wz, wc, nr
        hubop $0A5, $15A wz, wr, nr
        hubop $0A5, $15A wc, wr, nr
        hubop $0A5, $15A wz, wc, wr, nr
        hubop $0A5, $15A nr, wr
        hubop $0A5, $15A wc, nr, wz
        hubop $0A5, $15A wr, wz, nr
        hubop $15A, #$0A5
        hubop $15A, #$0A5 wz
        hubop $15A, #$0A5 wc
        hubop $15A, #$0A5 wr
        hubop $15A, #$0A5 nr
        hubop $15A, #$0A5 wz, wc
        hubop $15A, #$0A5 wz, wr
        hubop $15A, #$0A5 wz, nr
        hubop $15A, #$0A5 wc, wr
        hubop $15A, #$0A5 wc, nr
        hubop $15A, #$0A5 wr, nr
        hubop $15A, #$0A5 wz, wc, wr
        hubop $15A, #$0A5 wz, wc, nr
        hubop $15A, #$0A5 wz, wr, nr
        hubop $15A, #$0A5 wc, wr, nr
        hubop $15A, #$0A5 wz, wc, wr, nr
        hubop $15A, #$0A5 nr, wr
        hubop $15A, #$0A5 wc, nr, wz
        hubop $15A, #$0A5 wr, wz, nr
        clkset $0A5
        clkset $0A5 wz
        clkset $0A5 wc
        clkset $0A5 wr
        clkset $0A5 nr
        clkset $0A5 wz, wc
        clkset $0A5 wz, wr
        clkset $0A5 wz, nr
        clkset $0A5 wc, wr
        clkset $0A5 wc, nr
        clkset $0A5 wr, nr
        clkset $0A5 wz, wc, wr
        clkset $0A5 wz, wc, nr
        clkset $0A5 wz, wr, nr
        clkset $0A5 wc, wr, nr
        clkset $0A5 wz, wc, wr, nr
        clkset $0A5 nr, wr
        clkset $0A5 wc, nr, wz
        clkset $0A5 wr, wz, nr
        cogid $0A5
        cogid $0A5 wz
        cogid $0A5 wc
        cogid $0A5 wr
        cogid $0A5 nr
        cogid $0A5 wz, wc
        cogid $0A5 wz, wr
        cogid $0A5 wz, nr
        cogid $0A5 wc, wr
        cogid $0A5 wc, nr
        cogid $0A5 wr, nr
        cogid $0A5 wz, wc, wr
        cogid $0A5 wz, wc, nr
        cogid $0A5 wz, wr, nr
        cogid $0A5 wc, wr, nr
        cogid $0A5 wz, wc, wr, nr
        cogid $0A5 nr, wr
        cogid $0A5 wc, nr, wz
        cogid $0A5 wr, wz, nr
        coginit $0A5
        coginit $0A5 wz
        coginit $0A5 wc
        coginit $0A5 wr
        coginit $0A5 nr
        coginit $0A5 wz, wc
        coginit $0A5 wz, wr
        coginit $0A5 wz, nr
        coginit $0A5 wc, wr
        coginit $0A5 wc, nr
        coginit $0A5 wr, nr
        coginit $0A5 wz, wc, wr
        coginit $0A5 wz, wc, nr
        coginit $0A5 wz, wr, nr
        coginit $0A5 wc, wr, nr
        coginit $0A5 wz, wc, wr, nr
        coginit $0A5 nr, wr
        coginit $0A5 wc, nr, wz
        coginit $0A5 wr, wz, nr
        cogstop $0A5
        cogstop $0A5 wz
        cogstop $0A5 wc
        cogstop $0A5 wr
        cogstop $0A5 nr
        cogstop $0A5 wz, wc
        cogstop $0A5 wz, wr
        cogstop $0A5 wz, nr
        cogstop $0A5 wc, wr
        cogstop $0A5 wc, nr
        cogstop $0A5 wr, nr
        cogstop $0A5 wz, wc, wr
        cogstop $0A5 wz, wc, nr
        cogstop $0A5 wz, wr, nr
        cogstop $0A5 wc, wr, nr
        cogstop $0A5 wz, wc, wr, nr
        cogstop $0A5 nr, wr
        cogstop $0A5 wc, nr, wz
        cogstop $0A5 wr, wz, nr
        locknew $0A5
        locknew $0A5 wz
        locknew $0A5 wc
        locknew $0A5 wr
        locknew $0A5 nr
        locknew $0A5 wz, wc
        locknew $0A5 wz, wr
        locknew $0A5 wz, nr
        locknew $0A5 wc, wr
        locknew $0A5 wc, nr
        locknew $0A5 wr, nr
        locknew $0A5 wz, wc, wr
        locknew $0A5 wz, wc, nr
        locknew $0A5 wz, wr, nr
        locknew $0A5 wc, wr, nr
        locknew $0A5 wz, wc, wr, nr
        locknew $0A5 nr, wr
        locknew $0A5 wc, nr, wz
        locknew $0A5 wr, wz, nr
        lockret $0A5
        lockret $0A5 wz
        lockret $0A5 wc
        lockret $0A5 wr
        lockret $0A5 nr
        lockret $0A5 wz, wc
        lockret $0A5 wz, wr
        lockret $0A5 wz, nr
        lockret $0A5 wc, wr
        lockret $0A5 wc, nr
        lockret $0A5 wr, nr
        lockret $0A5 wz, wc, wr
        lockret $0A5 wz, wc, nr
        lockret $0A5 wz, wr, nr
        lockret $0A5 wc, wr, nr
        lockret $0A5 wz, wc, wr, nr
        lockret $0A5 nr, wr
        lockret $0A5 wc, nr, wz
        lockret $0A5 wr, wz, nr
        lockset $0A5
        lockset $0A5 wz
        lockset $0A5 wc
        lockset $0A5 wr
        lockset $0A5 nr
        lockset $0A5 wz, wc
        lockset $0A5 wz, wr
        lockset $0A5 wz, nr
        lockset $0A5 wc, wr
        lockset $0A5 wc, nr
        lockset $0A5 wr, nr
        lockset $0A5 wz, wc, wr
        lockset $0A5 wz, wc, nr
        lockset $0A5 wz, wr, nr
        lockset $0A5 wc, wr, nr
        lockset $0A5 wz, wc, wr, nr
        lockset $0A5 nr, wr
        lockset $0A5 wc, nr, wz
        lockset $0A5 wr, wz, nr
        lockclr $0A5
        lockclr $0A5 wz
        lockclr $0A5 wc
        lockclr $0A5 wr
        lockclr $0A5 nr
        lockclr $0A5 wz, wc
        lockclr $0A5 wz, wr
        lockclr $0A5 wz, nr
        lockclr $0A5 wc, wr
        lockclr $0A5 wc, nr
        lockclr $0A5 wr, nr
        lockclr $0A5 wz, wc, wr
        lockclr $0A5 wz, wc, nr
        lockclr $0A5 wz, wr, nr
        lockclr $0A5 wc, wr, nr
        lockclr $0A5 wz, wc, wr, nr
        lockclr $0A5 nr, wr
        lockclr $0A5 wc, nr, wz
        lockclr $0A5 wr, wz, nr
        ror $0A5, $15A
        ror $0A5, $15A wz
        ror $0A5, $15A wc
        ror $0A5, $15A wr
        ror $0A5, $15A nr
        ror $0A5, $15A wz, wc
        ror $0A5, $15A wz, wr
        ror $0A5, $15A wz, nr
        ror $0A5, $15A wc, wr
        ror $0A5, $15A wc, nr
        ror $0A5, $15A wr, nr
        ror $0A5, $15A wz, wc, wr
        ror $0A5, $15A wz, wc, nr
        ror $0A5, $15A wz, wr, nr
        ror $0A5, $15A wc, wr, nr
        ror $0A5, $15A wz, wc, wr, nr
        ror $0A5, $15A nr, wr
        ror $0A5, $15A wc, nr, wz
        org 0
        ror $0A5, $15A wr, wz, nr
        ror $15A, #$0A5
        ror $15A, #$0A5 wz
        ror $15A, #$0A5 wc
        ror $15A, #$0A5 wr
        ror $15A, #$0A5 nr
        ror $15A, #$0A5 wz, wc
        ror $15A, #$0A5 wz, wr
        ror $15A, #$0A5 wz, nr
        ror $15A, #$0A5 wc, wr
        ror $15A, #$0A5 wc, nr
        ror $15A, #$0A5 wr, nr
        ror $15A, #$0A5 wz, wc, wr
        ror $15A, #$0A5 wz, wc, nr
        ror $15A, #$0A5 wz, wr, nr
        ror $15A, #$0A5 wc, wr, nr
        ror $15A, #$0A5 wz, wc, wr, nr
        ror $15A, #$0A5 nr, wr
        ror $15A, #$0A5 wc, nr, wz
        ror $15A, #$0A5 wr, wz, nr
        rol $0A5, $15A
        rol $0A5, $15A wz
        rol $0A5, $15A wc
        rol $0A5, $15A wr
        rol $0A5, $15A nr
        rol $0A5, $15A wz, wc
        rol $0A5, $15A wz, wr
        rol $0A5, $15A wz, nr
        rol $0A5, $15A wc, wr
        rol $0A5, $15A wc, nr
        rol $0A5, $15A wr, nr
        rol $0A5, $15A wz, wc, wr
        rol $0A5, $15A wz, wc, nr
        rol $0A5, $15A wz, wr, nr
        rol $0A5, $15A wc, wr, nr
        rol $0A5, $15A wz, wc, wr, nr
        rol $0A5, $15A nr, wr
        rol $0A5, $15A wc, nr, wz
        rol $0A5, $15A wr, wz, nr
        rol $15A, #$0A5
        rol $15A, #$0A5 wz
        rol $15A, #$0A5 wc
        rol $15A, #$0A5 wr
        rol $15A, #$0A5 nr
        rol $15A, #$0A5 wz, wc
        rol $15A, #$0A5 wz, wr
        rol $15A, #$0A5 wz, nr
        rol $15A, #$0A5 wc, wr
        rol $15A, #$0A5 wc, nr
        rol $15A, #$0A5 wr, nr
        rol $15A, #$0A5 wz, wc, wr
        rol $15A, #$0A5 wz, wc, nr
        rol $15A, #$0A5 wz, wr, nr
        rol $15A, #$0A5 wc, wr, nr
        rol $15A, #$0A5 wz, wc, wr, nr
        rol $15A, #$0A5 nr, wr
        rol $15A, #$0A5 wc, nr, wz
        rol $15A, #$0A5 wr, wz, nr
        shr $0A5, $15A
        shr $0A5, $15A wz
        shr $0A5, $15A wc
        shr $0A5, $15A wr
        shr $0A5, $15A nr
        shr $0A5, $15A wz, wc
        shr $0A5, $15A wz, wr
        shr $0A5, $15A wz, nr
        shr $0A5, $15A wc, wr
        shr $0A5, $15A wc, nr
        shr $0A5, $15A wr, nr
        shr $0A5, $15A wz, wc, wr
        shr $0A5, $15A wz, wc, nr
        shr $0A5, $15A wz, wr, nr
        shr $0A5, $15A wc, wr, nr
        shr $0A5, $15A wz, wc, wr, nr
        shr $0A5, $15A nr, wr
        shr $0A5, $15A wc, nr, wz
        shr $0A5, $15A wr, wz, nr
        shr $15A, #$0A5
        shr $15A, #$0A5 wz
        shr $15A, #$0A5 wc
        shr $15A, #$0A5 wr
        shr $15A, #$0A5 nr
        shr $15A, #$0A5 wz, wc
        shr $15A, #$0A5 wz, wr
        shr $15A, #$0A5 wz, nr
        shr $15A, #$0A5 wc, wr
        shr $15A, #$0A5 wc, nr
        shr $15A, #$0A5 wr, nr
        shr $15A, #$0A5 wz, wc, wr
        shr $15A, #$0A5 wz, wc, nr
        shr $15A, #$0A5 wz, wr, nr
        shr $15A, #$0A5 wc, wr, nr
        shr $15A, #$0A5 wz, wc, wr, nr
        shr $15A, #$0A5 nr, wr
        shr $15A, #$0A5 wc, nr, wz
        shr $15A, #$0A5 wr, wz, nr
        shl $0A5, $15A
        shl $0A5, $15A wz
        shl $0A5, $15A wc
        shl $0A5, $15A wr
        shl $0A5, $15A nr
        shl $0A5, $15A wz, wc
        shl $0A5, $15A wz, wr
        shl $0A5, $15A wz, nr
        shl $0A5, $15A wc, wr
        shl $0A5, $15A wc, nr
        shl $0A5, $15A wr, nr
        shl $0A5, $15A wz, wc, wr
        shl $0A5, $15A wz, wc, nr
        shl $0A5, $15A wz, wr, nr
        shl $0A5, $15A wc, wr, nr
        shl $0A5, $15A wz, wc, wr, nr
        shl $0A5, $15A nr, wr
        shl $0A5, $15A wc, nr, wz
        shl $0A5, $15A wr, wz, nr
        shl $15A, #$0A5
        shl $15A, #$0A5 wz
        shl $15A, #$0A5 wc
        shl $15A, #$0A5 wr
        shl $15A, #$0A5 nr
        shl $15A, #$0A5 wz, wc
        shl $15A, #$0A5 wz, wr
        shl $15A, #$0A5 wz, nr
        shl $15A, #$0A5 wc, wr
        shl $15A, #$0A5 wc, nr
        shl $15A, #$0A5 wr, nr
        shl $15A, #$0A5 wz, wc, wr
        shl $15A, #$0A5 wz, wc, nr
        shl $15A, #$0A5 wz, wr, nr
        shl $15A, #$0A5 wc, wr, nr
        shl $15A, #$0A5 wz, wc, wr, nr
        shl $15A, #$0A5 nr, wr
        shl $15A, #$0A5 wc, nr, wz
        shl $15A, #$0A5 wr, wz, nr
        rcr $0A5, $15A
        rcr $0A5, $15A wz
        rcr $0A5, $15A wc
        rcr $0A5, $15A wr
        rcr $0A5, $15A nr
        rcr $0A5, $15A wz, wc
        rcr $0A5, $15A wz, wr
        rcr $0A5, $15A wz, nr
        rcr $0A5, $15A wc, wr
        rcr $0A5, $15A wc, nr
        rcr $0A5, $15A wr, nr
        rcr $0A5, $15A wz, wc, wr
        rcr $0A5, $15A wz, wc, nr
        rcr $0A5, $15A wz, wr, nr
        rcr $0A5, $15A wc, wr, nr
        rcr $0A5, $15A wz, wc, wr, nr
        rcr $0A5, $15A nr, wr
        rcr $0A5, $15A wc, nr, wz
        rcr $0A5, $15A wr, wz, nr
        rcr $15A, #$0A5
        rcr $15A, #$0A5 wz
        rcr $15A, #$0A5 wc
        rcr $15A, #$0A5 wr
        rcr $15A, #$0A5 nr
        rcr $15A, #$0A5 wz, wc
        rcr $15A, #$0A5 wz, wr
        rcr $15A, #$0A5 wz, nr
        rcr $15A, #$0A5 wc, wr
        rcr $15A, #$0A5 wc, nr
        rcr $15A, #$0A5 wr, nr
        rcr $15A, #$0A5 wz, wc, wr
        rcr $15A, #$0A5 wz, wc, nr
        rcr $15A, #$0A5 wz, wr, nr
        rcr $15A, #$0A5 wc, wr, nr
        rcr $15A, #$0A5 wz, wc, wr, nr
        rcr $15A, #$0A5 nr, wr
        rcr $15A, #$0A5 wc, nr, wz
        rcr $15A, #$0A5 wr, wz, nr
        rcl $0A5, $15A
        rcl $0A5, $15A wz
        rcl $0A5, $15A wc
        rcl $0A5, $15A wr
        rcl $0A5, $15A nr
        rcl $0A5, $15A wz, wc
        rcl $0A5, $15A wz, wr
        rcl $0A5, $15A wz, nr
        rcl $0A5, $15A wc, wr
        rcl $0A5, $15A wc, nr
        rcl $0A5, $15A wr, nr
        rcl $0A5, $15A wz, wc, wr
        rcl $0A5, $15A wz, wc, nr
        rcl $0A5, $15A wz, wr, nr
        rcl $0A5, $15A wc, wr, nr
        rcl $0A5, $15A wz, wc, wr, nr
        rcl $0A5, $15A nr, wr
        rcl $0A5, $15A wc, nr, wz
        rcl $0A5, $15A wr, wz, nr
        rcl $15A, #$0A5
        rcl $15A, #$0A5 wz
        rcl $15A, #$0A5 wc
        rcl $15A, #$0A5 wr
        rcl $15A, #$0A5 nr
        rcl $15A, #$0A5 wz, wc
        rcl $15A, #$0A5 wz, wr
        rcl $15A, #$0A5 wz, nr
        rcl $15A, #$0A5 wc, wr
        rcl $15A, #$0A5 wc, nr
        rcl $15A, #$0A5 wr, nr
        rcl $15A, #$0A5 wz, wc, wr
        rcl $15A, #$0A5 wz, wc, nr
        rcl $15A, #$0A5 wz, wr, nr
        rcl $15A, #$0A5 wc, wr, nr
        rcl $15A, #$0A5 wz, wc, wr, nr
        rcl $15A, #$0A5 nr, wr
        rcl $15A, #$0A5 wc, nr, wz
        rcl $15A, #$0A5 wr, wz, nr
        sar $0A5, $15A
        sar $0A5, $15A wz
        sar $0A5, $15A wc
        sar $0A5, $15A wr
        sar $0A5, $15A nr
        sar $0A5, $15A wz, wc
        sar $0A5, $15A wz, wr
        sar $0A5, $15A wz, nr
        sar $0A5, $15A wc, wr
        sar $0A5, $15A wc, nr
        sar $0A5, $15A wr, nr
        sar $0A5, $15A wz, wc, wr
        sar $0A5, $15A wz, wc, nr
        sar $0A5, $15A wz, wr, nr
        sar $0A5, $15A wc, wr, nr
        sar $0A5, $15A wz, wc, wr, nr
        sar $0A5, $15A nr, wr
        sar $0A5, $15A wc, nr, wz
        sar $0A5, $15A wr, wz, nr
        sar $15A, #$0A5
        sar $15A, #$0A5 wz
        sar $15A, #$0A5 wc
        sar $15A, #$0A5 wr
        sar $15A, #$0A5 nr
        sar $15A, #$0A5 wz, wc
        sar $15A, #$0A5 wz, wr
        sar $15A, #$0A5 wz, nr
        sar $15A, #$0A5 wc, wr
        sar $15A, #$0A5 wc, nr
        sar $15A, #$0A5 wr, nr
        sar $15A, #$0A5 wz, wc, wr
        sar $15A, #$0A5 wz, wc, nr
        sar $15A, #$0A5 wz, wr, nr
        sar $15A, #$0A5 wc, wr, nr
        sar $15A, #$0A5 wz, wc, wr, nr
        sar $15A, #$0A5 nr, wr
        sar $15A, #$0A5 wc, nr, wz
        sar $15A, #$0A5 wr, wz, nr
        rev $0A5, $15A
        rev $0A5, $15A wz
        rev $0A5, $15A wc
        rev $0A5, $15A wr
        rev $0A5, $15A nr
        rev $0A5, $15A wz, wc
        rev $0A5, $15A wz, wr
        rev $0A5, $15A wz, nr
        org 0
        rev $0A5, $15A wc, wr
        rev $0A5, $15A wc, nr
        rev $0A5, $15A wr, nr
        rev $0A5, $15A wz, wc, wr
        rev $0A5, $15A wz, wc, nr
        rev $0A5, $15A wz, wr, nr
        rev $0A5, $15A wc, wr, nr
        rev $0A5, $15A wz, wc, wr, nr
        rev $0A5, $15A nr, wr
        rev $0A5, $15A wc, nr, wz
        rev $0A5, $15A wr, wz, nr
        rev $15A, #$0A5
        rev $15A, #$0A5 wz
        rev $15A, #$0A5 wc
        rev $15A, #$0A5 wr
        rev $15A, #$0A5 nr
        rev $15A, #$0A5 wz, wc
        rev $15A, #$0A5 wz, wr
        rev $15A, #$0A5 wz, nr
        rev $15A, #$0A5 wc, wr
        rev $15A, #$0A5 wc, nr
        rev $15A, #$0A5 wr, nr
        rev $15A, #$0A5 wz, wc, wr
        rev $15A, #$0A5 wz, wc, nr
        rev $15A, #$0A5 wz, wr, nr
        rev $15A, #$0A5 wc, wr, nr
        rev $15A, #$0A5 wz, wc, wr, nr
        rev $15A, #$0A5 nr, wr
        rev $15A, #$0A5 wc, nr, wz
        rev $15A, #$0A5 wr, wz, nr
        mins $0A5, $15A
        mins $0A5, $15A wz
        mins $0A5, $15A wc
        mins $0A5, $15A wr
        mins $0A5, $15A nr
        mins $0A5, $15A wz, wc
        mins $0A5, $15A wz, wr
        mins $0A5, $15A wz, nr
        mins $0A5, $15A wc, wr
        mins $0A5, $15A wc, nr
        mins $0A5, $15A wr, nr
        mins $0A5, $15A wz, wc, wr
        mins $0A5, $15A wz, wc, nr
        mins $0A5, $15A wz, wr, nr
        mins $0A5, $15A wc, wr, nr
        mins $0A5, $15A wz, wc, wr, nr
        mins $0A5, $15A nr, wr
        mins $0A5, $15A wc, nr, wz
        mins $0A5, $15A wr, wz, nr
        mins $15A, #$0A5
        mins $15A, #$0A5 wz
        mins $15A, #$0A5 wc
        mins $15A, #$0A5 wr
        mins $15A, #$0A5 nr
        mins $15A, #$0A5 wz, wc
        mins $15A, #$0A5 wz, wr
        mins $15A, #$0A5 wz, nr
        mins $15A, #$0A5 wc, wr
        mins $15A, #$0A5 wc, nr
        mins $15A, #$0A5 wr, nr
        mins $15A, #$0A5 wz, wc, wr
        mins $15A, #$0A5 wz, wc, nr
        mins $15A, #$0A5 wz, wr, nr
        mins $15A, #$0A5 wc, wr, nr
        mins $15A, #$0A5 wz, wc, wr, nr
        mins $15A, #$0A5 nr, wr
        mins $15A, #$0A5 wc, nr, wz
        mins $15A, #$0A5 wr, wz, nr
        maxs $0A5, $15A
        maxs $0A5, $15A wz
        maxs $0A5, $15A wc
        maxs $0A5, $15A wr
        maxs $0A5, $15A nr
        maxs $0A5, $15A wz, wc
        maxs $0A5, $15A wz, wr
        maxs $0A5, $15A wz, nr
        maxs $0A5, $15A wc, wr
        maxs $0A5, $15A wc, nr
        maxs $0A5, $15A wr, nr
        maxs $0A5, $15A wz, wc, wr
        maxs $0A5, $15A wz, wc, nr
        maxs $0A5, $15A wz, wr, nr
        maxs $0A5, $15A wc, wr, nr
        maxs $0A5, $15A wz, wc, wr, nr
        maxs $0A5, $15A nr, wr
        maxs $0A5, $15A wc, nr, wz
        maxs $0A5, $15A wr, wz, nr
        maxs $15A, #$0A5
        maxs $15A, #$0A5 wz
        maxs $15A, #$0A5 wc
        maxs $15A, #$0A5 wr
        maxs $15A, #$0A5 nr
        maxs $15A, #$0A5 wz, wc
        maxs $15A, #$0A5 wz, wr
        maxs $15A, #$0A5 wz, nr
        maxs $15A, #$0A5 wc, wr
        maxs $15A, #$0A5 wc, nr
        maxs $15A, #$0A5 wr, nr
        maxs $15A, #$0A5 wz, wc, wr
        maxs $15A, #$0A5 wz, wc, nr
        maxs $15A, #$0A5 wz, wr, nr
        maxs $15A, #$0A5 wc, wr, nr
        maxs $15A, #$0A5 wz, wc, wr, nr
        maxs $15A, #$0A5 nr, wr
        maxs $15A, #$0A5 wc, nr, wz
        maxs $15A, #$0A5 wr, wz, nr
        min $0A5, $15A
        min $0A5, $15A wz
        min $0A5, $15A wc
        min $0A5, $15A wr
        min $0A5, $15A nr
        min $0A5, $15A wz, wc
        min $0A5, $15A wz, wr
        min $0A5, $15A wz, nr
        min $0A5, $15A wc, wr
        min $0A5, $15A wc, nr
        min $0A5, $15A wr, nr
        min $0A5, $15A wz, wc, wr
        min $0A5, $15A wz, wc, nr
        min $0A5, $15A wz, wr, nr
        min $0A5, $15A wc, wr, nr
        min $0A5, $15A wz, wc, wr, nr
        min $0A5, $15A nr, wr
        min $0A5, $15A wc, nr, wz
        min $0A5, $15A wr, wz, nr
        min $15A, #$0A5
        min $15A, #$0A5 wz
        min $15A, #$0A5 wc
        min $15A, #$0A5 wr
        min $15A, #$0A5 nr
        min $15A, #$0A5 wz, wc
        min $15A, #$0A5 wz, wr
        min $15A, #$0A5 wz, nr
        min $15A, #$0A5 wc, wr
        min $15A, #$0A5 wc, nr
        min $15A, #$0A5 wr, nr
        min $15A, #$0A5 wz, wc, wr
        min $15A, #$0A5 wz, wc, nr
        min $15A, #$0A5 wz, wr, nr
        min $15A, #$0A5 wc, wr, nr
        min $15A, #$0A5 wz, wc, wr, nr
        min $15A, #$0A5 nr, wr
        min $15A, #$0A5 wc, nr, wz
        min $15A, #$0A5 wr, wz, nr
        max $0A5, $15A
        max $0A5, $15A wz
        max $0A5, $15A wc
        max $0A5, $15A wr
        max $0A5, $15A nr
        max $0A5, $15A wz, wc
        max $0A5, $15A wz, wr
        max $0A5, $15A wz, nr
        max $0A5, $15A wc, wr
        max $0A5, $15A wc, nr
        max $0A5, $15A wr, nr
        max $0A5, $15A wz, wc, wr
        max $0A5, $15A wz, wc, nr
        max $0A5, $15A wz, wr, nr
        max $0A5, $15A wc, wr, nr
        max $0A5, $15A wz, wc, wr, nr
        max $0A5, $15A nr, wr
        max $0A5, $15A wc, nr, wz
        max $0A5, $15A wr, wz, nr
        max $15A, #$0A5
        max $15A, #$0A5 wz
        max $15A, #$0A5 wc
        max $15A, #$0A5 wr
        max $15A, #$0A5 nr
        max $15A, #$0A5 wz, wc
        max $15A, #$0A5 wz, wr
        max $15A, #$0A5 wz, nr
        max $15A, #$0A5 wc, wr
        max $15A, #$0A5 wc, nr
        max $15A, #$0A5 wr, nr
        max $15A, #$0A5 wz, wc, wr
        max $15A, #$0A5 wz, wc, nr
        max $15A, #$0A5 wz, wr, nr
        max $15A, #$0A5 wc, wr, nr
        max $15A, #$0A5 wz, wc, wr, nr
        max $15A, #$0A5 nr, wr
        max $15A, #$0A5 wc, nr, wz
        max $15A, #$0A5 wr, wz, nr
        movs $0A5, $15A
        movs $0A5, $15A wz
        movs $0A5, $15A wc
        movs $0A5, $15A wr
        movs $0A5, $15A nr
        movs $0A5, $15A wz, wc
        movs $0A5, $15A wz, wr
        movs $0A5, $15A wz, nr
        movs $0A5, $15A wc, wr
        movs $0A5, $15A wc, nr
        movs $0A5, $15A wr, nr
        movs $0A5, $15A wz, wc, wr
        movs $0A5, $15A wz, wc, nr
        movs $0A5, $15A wz, wr, nr
        movs $0A5, $15A wc, wr, nr
        movs $0A5, $15A wz, wc, wr, nr
        movs $0A5, $15A nr, wr
        movs $0A5, $15A wc, nr, wz
        movs $0A5, $15A wr, wz, nr
        movs $15A, #$0A5
        movs $15A, #$0A5 wz
        movs $15A, #$0A5 wc
        movs $15A, #$0A5 wr
        movs $15A, #$0A5 nr
        movs $15A, #$0A5 wz, wc
        movs $15A, #$0A5 wz, wr
        movs $15A, #$0A5 wz, nr
        movs $15A, #$0A5 wc, wr
        movs $15A, #$0A5 wc, nr
        movs $15A, #$0A5 wr, nr
        movs $15A, #$0A5 wz, wc, wr
        movs $15A, #$0A5 wz, wc, nr
        movs $15A, #$0A5 wz, wr, nr
        movs $15A, #$0A5 wc, wr, nr
        movs $15A, #$0A5 wz, wc, wr, nr
        movs $15A, #$0A5 nr, wr
        movs $15A, #$0A5 wc, nr, wz
        movs $15A, #$0A5 wr, wz, nr
        movd $0A5, $15A
        movd $0A5, $15A wz
        movd $0A5, $15A wc
        movd $0A5, $15A wr
        movd $0A5, $15A nr
        movd $0A5, $15A wz, wc
        movd $0A5, $15A wz, wr
        movd $0A5, $15A wz, nr
        movd $0A5, $15A wc, wr
        movd $0A5, $15A wc, nr
        movd $0A5, $15A wr, nr
        movd $0A5, $15A wz, wc, wr
        movd $0A5, $15A wz, wc, nr
        movd $0A5, $15A wz, wr, nr
        movd $0A5, $15A wc, wr, nr
        movd $0A5, $15A wz, wc, wr, nr
        movd $0A5, $15A nr, wr
        movd $0A5, $15A wc, nr, wz
        movd $0A5, $15A wr, wz, nr
        movd $15A, #$0A5
        movd $15A, #$0A5 wz
        movd $15A, #$0A5 wc
        movd $15A, #$0A5 wr
        movd $15A, #$0A5 nr
        movd $15A, #$0A5 wz, wc
        movd $15A, #$0A5 wz, wr
        movd $15A, #$0A5 wz, nr
        movd $15A, #$0A5 wc, wr
        movd $15A, #$0A5 wc, nr
        movd $15A, #$0A5 wr, nr
        movd $15A, #$0A5 wz, wc, wr
        movd $15A, #$0A5 wz, wc, nr
        movd $15A, #$0A5 wz, wr, nr
        movd $15A, #$0A5 wc, wr, nr
        movd $15A, #$0A5 wz, wc, wr, nr
        movd $15A, #$0A5 nr, wr
        org 0
        movd $15A, #$0A5 wc, nr, wz
        movd $15A, #$0A5 wr, wz, nr
        movi $0A5, $15A
        movi $0A5, $15A wz
        movi $0A5, $15A wc
        movi $0A5, $15A wr
        movi $0A5, $15A nr
        movi $0A5, $15A wz, wc
        movi $0A5, $15A wz, wr
        movi $0A5, $15A wz, nr
        movi $0A5, $15A wc, wr
        movi $0A5, $15A wc, nr
        movi $0A5, $15A wr, nr
        movi $0A5, $15A wz, wc, wr
        movi $0A5, $15A wz, wc, nr
        movi $0A5, $15A wz, wr, nr
        movi $0A5, $15A wc, wr, nr
        movi $0A5, $15A wz, wc, wr, nr
        movi $0A5, $15A nr, wr
        movi $0A5, $15A wc, nr, wz
        movi $0A5, $15A wr, wz, nr
        movi $15A, #$0A5
        movi $15A, #$0A5 wz
        movi $15A, #$0A5 wc
        movi $15A, #$0A5 wr
        movi $15A, #$0A5 nr
        movi $15A, #$0A5 wz, wc
        movi $15A, #$0A5 wz, wr
        movi $15A, #$0A5 wz, nr
        movi $15A, #$0A5 wc, wr
        movi $15A, #$0A5 wc, nr
        movi $15A, #$0A5 wr, nr
        movi $15A, #$0A5 wz, wc, wr
        movi $15A, #$0A5 wz, wc, nr
        movi $15A, #$0A5 wz, wr, nr
        movi $15A, #$0A5 wc, wr, nr
        movi $15A, #$0A5 wz, wc, wr, nr
        movi $15A, #$0A5 nr, wr
        movi $15A, #$0A5 wc, nr, wz
        movi $15A, #$0A5 wr, wz, nr
        jmpret $0A5, $15A
        jmpret $0A5, $15A wz
        jmpret $0A5, $15A wc
        jmpret $0A5, $15A wr
        jmpret $0A5, $15A nr
        jmpret $0A5, $15A wz, wc
        jmpret $0A5, $15A wz, wr
        jmpret $0A5, $15A wz, nr
        jmpret $0A5, $15A wc, wr
        jmpret $0A5, $15A wc, nr
        jmpret $0A5, $15A wr, nr
        jmpret $0A5, $15A wz, wc, wr
        jmpret $0A5, $15A wz, wc, nr
        jmpret $0A5, $15A wz, wr, nr
        jmpret $0A5, $15A wc, wr, nr
        jmpret $0A5, $15A wz, wc, wr, nr
        jmpret $0A5, $15A nr, wr
        jmpret $0A5, $15A wc, nr, wz
        jmpret $0A5, $15A wr, wz, nr
        jmpret $15A, #$0A5
        jmpret $15A, #$0A5 wz
        jmpret $15A, #$0A5 wc
        jmpret $15A, #$0A5 wr
        jmpret $15A, #$0A5 nr
        jmpret $15A, #$0A5 wz, wc
        jmpret $15A, #$0A5 wz, wr
        jmpret $15A, #$0A5 wz, nr
        jmpret $15A, #$0A5 wc, wr
        jmpret $15A, #$0A5 wc, nr
        jmpret $15A, #$0A5 wr, nr
        jmpret $15A, #$0A5 wz, wc, wr
        jmpret $15A, #$0A5 wz, wc, nr
        jmpret $15A, #$0A5 wz, wr, nr
        jmpret $15A, #$0A5 wc, wr, nr
        jmpret $15A, #$0A5 wz, wc, wr, nr
        jmpret $15A, #$0A5 nr, wr
        jmpret $15A, #$0A5 wc, nr, wz
        jmpret $15A, #$0A5 wr, wz, nr
        jmp $0A5
        jmp $0A5 wz
        jmp $0A5 wc
        jmp $0A5 wr
        jmp $0A5 nr
        jmp $0A5 wz, wc
        jmp $0A5 wz, wr
        jmp $0A5 wz, nr
        jmp $0A5 wc, wr
        jmp $0A5 wc, nr
        jmp $0A5 wr, nr
        jmp $0A5 wz, wc, wr
        jmp $0A5 wz, wc, nr
        jmp $0A5 wz, wr, nr
        jmp $0A5 wc, wr, nr
        jmp $0A5 wz, wc, wr, nr
        jmp $0A5 nr, wr
        jmp $0A5 wc, nr, wz
        jmp $0A5 wr, wz, nr
        jmp #$15A
        jmp #$15A wz
        jmp #$15A wc
        jmp #$15A wr
        jmp #$15A nr
        jmp #$15A wz, wc
        jmp #$15A wz, wr
        jmp #$15A wz, nr
        jmp #$15A wc, wr
        jmp #$15A wc, nr
        jmp #$15A wr, nr
        jmp #$15A wz, wc, wr
        jmp #$15A wz, wc, nr
        jmp #$15A wz, wr, nr
        jmp #$15A wc, wr, nr
        jmp #$15A wz, wc, wr, nr
        jmp #$15A nr, wr
        jmp #$15A wc, nr, wz
        jmp #$15A wr, wz, nr
        call #lab
        call #lab wz
        call #lab wc
        call #lab wr
        call #lab nr
        call #lab wz, wc
        call #lab wz, wr
        call #lab wz, nr
        call #lab wc, wr
        call #lab wc, nr
        call #lab wr, nr
        call #lab wz, wc, wr
        call #lab wz, wc, nr
        call #lab wz, wr, nr
        call #lab wc, wr, nr
        call #lab wz, wc, wr, nr
        call #lab nr, wr
        call #lab wc, nr, wz
        call #lab wr, wz, nr
        ret
        ret wz
        ret wc
        ret wr
        ret nr
        ret wz, wc
        ret wz, wr
        ret wz, nr
        ret wc, wr
        ret wc, nr
        ret wr, nr
        ret wz, wc, wr
        ret wz, wc, nr
        ret wz, wr, nr
        ret wc, wr, nr
        ret wz, wc, wr, nr
        ret nr, wr
        ret wc, nr, wz
        ret wr, wz, nr
        test $0A5, $15A
        test $0A5, $15A wz
        test $0A5, $15A wc
        test $0A5, $15A wr
        test $0A5, $15A nr
        test $0A5, $15A wz, wc
        test $0A5, $15A wz, wr
        test $0A5, $15A wz, nr
        test $0A5, $15A wc, wr
        test $0A5, $15A wc, nr
        test $0A5, $15A wr, nr
        test $0A5, $15A wz, wc, wr
        test $0A5, $15A wz, wc, nr
        test $0A5, $15A wz, wr, nr
        test $0A5, $15A wc, wr, nr
        test $0A5, $15A wz, wc, wr, nr
        test $0A5, $15A nr, wr
        test $0A5, $15A wc, nr, wz
        test $0A5, $15A wr, wz, nr
        test $15A, #$0A5
        test $15A, #$0A5 wz
        test $15A, #$0A5 wc
        test $15A, #$0A5 wr
        test $15A, #$0A5 nr
        test $15A, #$0A5 wz, wc
        test $15A, #$0A5 wz, wr
        test $15A, #$0A5 wz, nr
        test $15A, #$0A5 wc, wr
        test $15A, #$0A5 wc, nr
        test $15A, #$0A5 wr, nr
        test $15A, #$0A5 wz, wc, wr
        test $15A, #$0A5 wz, wc, nr
        test $15A, #$0A5 wz, wr, nr
        test $15A, #$0A5 wc, wr, nr
        test $15A, #$0A5 wz, wc, wr, nr
        test $15A, #$0A5 nr, wr
        test $15A, #$0A5 wc, nr, wz
        test $15A, #$0A5 wr, wz, nr
        and $0A5, $15A
        and $0A5, $15A wz
        and $0A5, $15A wc
        and $0A5, $15A wr
        and $0A5, $15A nr
        and $0A5, $15A wz, wc
        and $0A5, $15A wz, wr
        and $0A5, $15A wz, nr
        and $0A5, $15A wc, wr
        and $0A5, $15A wc, nr
        and $0A5, $15A wr, nr
        and $0A5, $15A wz, wc, wr
        and $0A5, $15A wz, wc, nr
        and $0A5, $15A wz, wr, nr
        and $0A5, $15A wc, wr, nr
        and $0A5, $15A wz, wc, wr, nr
        and $0A5, $15A nr, wr
        and $0A5, $15A wc, nr, wz
        and $0A5, $15A wr, wz, nr
        and $15A, #$0A5
        and $15A, #$0A5 wz
        and $15A, #$0A5 wc
        and $15A, #$0A5 wr
        and $15A, #$0A5 nr
        and $15A, #$0A5 wz, wc
        and $15A, #$0A5 wz, wr
        and $15A, #$0A5 wz, nr
        and $15A, #$0A5 wc, wr
        and $15A, #$0A5 wc, nr
        and $15A, #$0A5 wr, nr
        and $15A, #$0A5 wz, wc, wr
        and $15A, #$0A5 wz, wc, nr
        and $15A, #$0A5 wz, wr, nr
        and $15A, #$0A5 wc, wr, nr
        and $15A, #$0A5 wz, wc, wr, nr
        and $15A, #$0A5 nr, wr
        and $15A, #$0A5 wc, nr, wz
        and $15A, #$0A5 wr, wz, nr
        testn $0A5, $15A
        testn $0A5, $15A wz
        testn $0A5, $15A wc
        testn $0A5, $15A wr
        testn $0A5, $15A nr
        testn $0A5, $15A wz, wc
        testn $0A5, $15A wz, wr
        testn $0A5, $15A wz, nr
        testn $0A5, $15A wc, wr
        testn $0A5, $15A wc, nr
        testn $0A5, $15A wr, nr
        testn $0A5, $15A wz, wc, wr
        testn $0A5, $15A wz, wc, nr
        testn $0A5, $15A wz, wr, nr
        testn $0A5, $15A wc, wr, nr
        testn $0A5, $15A wz, wc, wr, nr
        testn $0A5, $15A nr, wr
        testn $0A5, $15A wc, nr, wz
        testn $0A5, $15A wr, wz, nr
        testn $15A, #$0A5
        testn $15A, #$0A5 wz
        testn $15A, #$0A5 wc
        testn $15A, #$0A5 wr
        testn $15A, #$0A5 nr
        testn $15A, #$0A5 wz, wc
        testn $15A, #$0A5 wz, wr
        org 0
        testn $15A, #$0A5 wz, nr
        testn $15A, #$0A5 wc, wr
        testn $15A, #$0A5 wc, nr
        testn $15A, #$0A5 wr, nr
        testn $15A, #$0A5 wz, wc, wr
        testn $15A, #$0A5 wz, wc, nr
        testn $15A, #$0A5 wz, wr, nr
        testn $15A, #$0A5 wc, wr, nr
        testn $15A, #$0A5 wz, wc, wr, nr
        testn $15A, #$0A5 nr, wr
        testn $15A, #$0A5 wc, nr, wz
        testn $15A, #$0A5 wr, wz, nr
        andn $0A5, $15A
        andn $0A5, $15A wz
        andn $0A5, $15A wc
        andn $0A5, $15A wr
        andn $0A5, $15A nr
        andn $0A5, $15A wz, wc
        andn $0A5, $15A wz, wr
        andn $0A5, $15A wz, nr
        andn $0A5, $15A wc, wr
        andn $0A5, $15A wc, nr
        andn $0A5, $15A wr, nr
        andn $0A5, $15A wz, wc, wr
        andn $0A5, $15A wz, wc, nr
        andn $0A5, $15A wz, wr, nr
        andn $0A5, $15A wc, wr, nr
        andn $0A5, $15A wz, wc, wr, nr
        andn $0A5, $15A nr, wr
        andn $0A5, $15A wc, nr, wz
        andn $0A5, $15A wr, wz, nr
        andn $15A, #$0A5
        andn $15A, #$0A5 wz
        andn $15A, #$0A5 wc
        andn $15A, #$0A5 wr
        andn $15A, #$0A5 nr
        andn $15A, #$0A5 wz, wc
        andn $15A, #$0A5 wz, wr
        andn $15A, #$0A5 wz, nr
        andn $15A, #$0A5 wc, wr
        andn $15A, #$0A5 wc, nr
        andn $15A, #$0A5 wr, nr
        andn $15A, #$0A5 wz, wc, wr
        andn $15A, #$0A5 wz, wc, nr
        andn $15A, #$0A5 wz, wr, nr
        andn $15A, #$0A5 wc, wr, nr
        andn $15A, #$0A5 wz, wc, wr, nr
        andn $15A, #$0A5 nr, wr
        andn $15A, #$0A5 wc, nr, wz
        andn $15A, #$0A5 wr, wz, nr
        or $0A5, $15A
        or $0A5, $15A wz
        or $0A5, $15A wc
        or $0A5, $15A wr
        or $0A5, $15A nr
        or $0A5, $15A wz, wc
        or $0A5, $15A wz, wr
        or $0A5, $15A wz, nr
        or $0A5, $15A wc, wr
        or $0A5, $15A wc, nr
        or $0A5, $15A wr, nr
        or $0A5, $15A wz, wc, wr
        or $0A5, $15A wz, wc, nr
        or $0A5, $15A wz, wr, nr
        or $0A5, $15A wc, wr, nr
        or $0A5, $15A wz, wc, wr, nr
        or $0A5, $15A nr, wr
        or $0A5, $15A wc, nr, wz
        or $0A5, $15A wr, wz, nr
        or $15A, #$0A5
        or $15A, #$0A5 wz
        or $15A, #$0A5 wc
        or $15A, #$0A5 wr
        or $15A, #$0A5 nr
        or $15A, #$0A5 wz, wc
        or $15A, #$0A5 wz, wr
        or $15A, #$0A5 wz, nr
        or $15A, #$0A5 wc, wr
        or $15A, #$0A5 wc, nr
        or $15A, #$0A5 wr, nr
        or $15A, #$0A5 wz, wc, wr
        or $15A, #$0A5 wz, wc, nr
        or $15A, #$0A5 wz, wr, nr
        or $15A, #$0A5 wc, wr, nr
        or $15A, #$0A5 wz, wc, wr, nr
        or $15A, #$0A5 nr, wr
        or $15A, #$0A5 wc, nr, wz
        or $15A, #$0A5 wr, wz, nr
        xor $0A5, $15A
        xor $0A5, $15A wz
        xor $0A5, $15A wc
        xor $0A5, $15A wr
        xor $0A5, $15A nr
        xor $0A5, $15A wz, wc
        xor $0A5, $15A wz, wr
        xor $0A5, $15A wz, nr
        xor $0A5, $15A wc, wr
        xor $0A5, $15A wc, nr
        xor $0A5, $15A wr, nr
        xor $0A5, $15A wz, wc, wr
        xor $0A5, $15A wz, wc, nr
        xor $0A5, $15A wz, wr, nr
        xor $0A5, $15A wc, wr, nr
        xor $0A5, $15A wz, wc, wr, nr
        xor $0A5, $15A nr, wr
        xor $0A5, $15A wc, nr, wz
        xor $0A5, $15A wr, wz, nr
        xor $15A, #$0A5
        xor $15A, #$0A5 wz
        xor $15A, #$0A5 wc
        xor $15A, #$0A5 wr
        xor $15A, #$0A5 nr
        xor $15A, #$0A5 wz, wc
        xor $15A, #$0A5 wz, wr
        xor $15A, #$0A5 wz, nr
        xor $15A, #$0A5 wc, wr
        xor $15A, #$0A5 wc, nr
        xor $15A, #$0A5 wr, nr
        xor $15A, #$0A5 wz, wc, wr
        xor $15A, #$0A5 wz, wc, nr
        xor $15A, #$0A5 wz, wr, nr
        xor $15A, #$0A5 wc, wr, nr
        xor $15A, #$0A5 wz, wc, wr, nr
        xor $15A, #$0A5 nr, wr
        xor $15A, #$0A5 wc, nr, wz
        xor $15A, #$0A5 wr, wz, nr
        muxc $0A5, $15A
        muxc $0A5, $15A wz
        muxc $0A5, $15A wc
        muxc $0A5, $15A wr
        muxc $0A5, $15A nr
        muxc $0A5, $15A wz, wc
        muxc $0A5, $15A wz, wr
        muxc $0A5, $15A wz, nr
        muxc $0A5, $15A wc, wr
        muxc $0A5, $15A wc, nr
        muxc $0A5, $15A wr, nr
        muxc $0A5, $15A wz, wc, wr
        muxc $0A5, $15A wz, wc, nr
        muxc $0A5, $15A wz, wr, nr
        muxc $0A5, $15A wc, wr, nr
        muxc $0A5, $15A wz, wc, wr, nr
        muxc $0A5, $15A nr, wr
        muxc $0A5, $15A wc, nr, wz
        muxc $0A5, $15A wr, wz, nr
        muxc $15A, #$0A5
        muxc $15A, #$0A5 wz
        muxc $15A, #$0A5 wc
        muxc $15A, #$0A5 wr
        muxc $15A, #$0A5 nr
        muxc $15A, #$0A5 wz, wc
        muxc $15A, #$0A5 wz, wr
        muxc $15A, #$0A5 wz, nr
        muxc $15A, #$0A5 wc, wr
        muxc $15A, #$0A5 wc, nr
        muxc $15A, #$0A5 wr, nr
        muxc $15A, #$0A5 wz, wc, wr
        muxc $15A, #$0A5 wz, wc, nr
        muxc $15A, #$0A5 wz, wr, nr
        muxc $15A, #$0A5 wc, wr, nr
        muxc $15A, #$0A5 wz, wc, wr, nr
        muxc $15A, #$0A5 nr, wr
        muxc $15A, #$0A5 wc, nr, wz
        muxc $15A, #$0A5 wr, wz, nr
        muxnc $0A5, $15A
        muxnc $0A5, $15A wz
        muxnc $0A5, $15A wc
        muxnc $0A5, $15A wr
        muxnc $0A5, $15A nr
        muxnc $0A5, $15A wz, wc
        muxnc $0A5, $15A wz, wr
        muxnc $0A5, $15A wz, nr
        muxnc $0A5, $15A wc, wr
        muxnc $0A5, $15A wc, nr
        muxnc $0A5, $15A wr, nr
        muxnc $0A5, $15A wz, wc, wr
        muxnc $0A5, $15A wz, wc, nr
        muxnc $0A5, $15A wz, wr, nr
        muxnc $0A5, $15A wc, wr, nr
        muxnc $0A5, $15A wz, wc, wr, nr
        muxnc $0A5, $15A nr, wr
        muxnc $0A5, $15A wc, nr, wz
        muxnc $0A5, $15A wr, wz, nr
        muxnc $15A, #$0A5
        muxnc $15A, #$0A5 wz
        muxnc $15A, #$0A5 wc
        muxnc $15A, #$0A5 wr
        muxnc $15A, #$0A5 nr
        muxnc $15A, #$0A5 wz, wc
        muxnc $15A, #$0A5 wz, wr
        muxnc $15A, #$0A5 wz, nr
        muxnc $15A, #$0A5 wc, wr
        muxnc $15A, #$0A5 wc, nr
        muxnc $15A, #$0A5 wr, nr
        muxnc $15A, #$0A5 wz, wc, wr
        muxnc $15A, #$0A5 wz, wc, nr
        muxnc $15A, #$0A5 wz, wr, nr
        muxnc $15A, #$0A5 wc, wr, nr
        muxnc $15A, #$0A5 wz, wc, wr, nr
        muxnc $15A, #$0A5 nr, wr
        muxnc $15A, #$0A5 wc, nr, wz
        muxnc $15A, #$0A5 wr, wz, nr
        muxz $0A5, $15A
        muxz $0A5, $15A wz
        muxz $0A5, $15A wc
        muxz $0A5, $15A wr
        muxz $0A5, $15A nr
        muxz $0A5, $15A wz, wc
        muxz $0A5, $15A wz, wr
        muxz $0A5, $15A wz, nr
        muxz $0A5, $15A wc, wr
        muxz $0A5, $15A wc, nr
        muxz $0A5, $15A wr, nr
        muxz $0A5, $15A wz, wc, wr
        muxz $0A5, $15A wz, wc, nr
        muxz $0A5, $15A wz, wr, nr
        muxz $0A5, $15A wc, wr, nr
        muxz $0A5, $15A wz, wc, wr, nr
        muxz $0A5, $15A nr, wr
        muxz $0A5, $15A wc, nr, wz
        muxz $0A5, $15A wr, wz, nr
        muxz $15A, #$0A5
        muxz $15A, #$0A5 wz
        muxz $15A, #$0A5 wc
        muxz $15A, #$0A5 wr
        muxz $15A, #$0A5 nr
        muxz $15A, #$0A5 wz, wc
        muxz $15A, #$0A5 wz, wr
        muxz $15A, #$0A5 wz, nr
        muxz $15A, #$0A5 wc, wr
        muxz $15A, #$0A5 wc, nr
        muxz $15A, #$0A5 wr, nr
        muxz $15A, #$0A5 wz, wc, wr
        muxz $15A, #$0A5 wz, wc, nr
        muxz $15A, #$0A5 wz, wr, nr
        muxz $15A, #$0A5 wc, wr, nr
        muxz $15A, #$0A5 wz, wc, wr, nr
        muxz $15A, #$0A5 nr, wr
        muxz $15A, #$0A5 wc, nr, wz
        muxz $15A, #$0A5 wr, wz, nr
        muxnz $0A5, $15A
        muxnz $0A5, $15A wz
        muxnz $0A5, $15A wc
        muxnz $0A5, $15A wr
        muxnz $0A5, $15A nr
        muxnz $0A5, $15A wz, wc
        muxnz $0A5, $15A wz, wr
        muxnz $0A5, $15A wz, nr
        muxnz $0A5, $15A wc, wr
        muxnz $0A5, $15A wc, nr
        muxnz $0A5, $15A wr, nr
        muxnz $0A5, $15A wz, wc, wr
        muxnz $0A5, $15A wz, wc, nr
        muxnz $0A5, $15A wz, wr, nr
        muxnz $0A5, $15A wc, wr, nr
        muxnz $0A5, $15A wz, wc, wr, nr
        org 0
        muxnz $0A5, $15A nr, wr
        muxnz $0A5, $15A wc, nr, wz
        muxnz $0A5, $15A wr, wz, nr
        muxnz $15A, #$0A5
        muxnz $15A, #$0A5 wz
        muxnz $15A, #$0A5 wc
        muxnz $15A, #$0A5 wr
        muxnz $15A, #$0A5 nr
        muxnz $15A, #$0A5 wz, wc
        muxnz $15A, #$0A5 wz, wr
        muxnz $15A, #$0A5 wz, nr
        muxnz $15A, #$0A5 wc, wr
        muxnz $15A, #$0A5 wc, nr
        muxnz $15A, #$0A5 wr, nr
        muxnz $15A, #$0A5 wz, wc, wr
        muxnz $15A, #$0A5 wz, wc, nr
        muxnz $15A, #$0A5 wz, wr, nr
        muxnz $15A, #$0A5 wc, wr, nr
        muxnz $15A, #$0A5 wz, wc, wr, nr
        muxnz $15A, #$0A5 nr, wr
        muxnz $15A, #$0A5 wc, nr, wz
        muxnz $15A, #$0A5 wr, wz, nr
        add $0A5, $15A
        add $0A5, $15A wz
        add $0A5, $15A wc
        add $0A5, $15A wr
        add $0A5, $15A nr
        add $0A5, $15A wz, wc
        add $0A5, $15A wz, wr
        add $0A5, $15A wz, nr
        add $0A5, $15A wc, wr
        add $0A5, $15A wc, nr
        add $0A5, $15A wr, nr
        add $0A5, $15A wz, wc, wr
        add $0A5, $15A wz, wc, nr
        add $0A5, $15A wz, wr, nr
        add $0A5, $15A wc, wr, nr
        add $0A5, $15A wz, wc, wr, nr
        add $0A5, $15A nr, wr
        add $0A5, $15A wc, nr, wz
        add $0A5, $15A wr, wz, nr
        add $15A, #$0A5
        add $15A, #$0A5 wz
        add $15A, #$0A5 wc
        add $15A, #$0A5 wr
        add $15A, #$0A5 nr
        add $15A, #$0A5 wz, wc
        add $15A, #$0A5 wz, wr
        add $15A, #$0A5 wz, nr
        add $15A, #$0A5 wc, wr
        add $15A, #$0A5 wc, nr
        add $15A, #$0A5 wr, nr
        add $15A, #$0A5 wz, wc, wr
        add $15A, #$0A5 wz, wc, nr
        add $15A, #$0A5 wz, wr, nr
        add $15A, #$0A5 wc, wr, nr
        add $15A, #$0A5 wz, wc, wr, nr
        add $15A, #$0A5 nr, wr
        add $15A, #$0A5 wc, nr, wz
        add $15A, #$0A5 wr, wz, nr
        cmp $0A5, $15A
        cmp $0A5, $15A wz
        cmp $0A5, $15A wc
        cmp $0A5, $15A wr
        cmp $0A5, $15A nr
        cmp $0A5, $15A wz, wc
        cmp $0A5, $15A wz, wr
        cmp $0A5, $15A wz, nr
        cmp $0A5, $15A wc, wr
        cmp $0A5, $15A wc, nr
        cmp $0A5, $15A wr, nr
        cmp $0A5, $15A wz, wc, wr
        cmp $0A5, $15A wz, wc, nr
        cmp $0A5, $15A wz, wr, nr
        cmp $0A5, $15A wc, wr, nr
        cmp $0A5, $15A wz, wc, wr, nr
        cmp $0A5, $15A nr, wr
        cmp $0A5, $15A wc, nr, wz
        cmp $0A5, $15A wr, wz, nr
        cmp $15A, #$0A5
        cmp $15A, #$0A5 wz
        cmp $15A, #$0A5 wc
        cmp $15A, #$0A5 wr
        cmp $15A, #$0A5 nr
        cmp $15A, #$0A5 wz, wc
        cmp $15A, #$0A5 wz, wr
        cmp $15A, #$0A5 wz, nr
        cmp $15A, #$0A5 wc, wr
        cmp $15A, #$0A5 wc, nr
        cmp $15A, #$0A5 wr, nr
        cmp $15A, #$0A5 wz, wc, wr
        cmp $15A, #$0A5 wz, wc, nr
        cmp $15A, #$0A5 wz, wr, nr
        cmp $15A, #$0A5 wc, wr, nr
        cmp $15A, #$0A5 wz, wc, wr, nr
        cmp $15A, #$0A5 nr, wr
        cmp $15A, #$0A5 wc, nr, wz
        cmp $15A, #$0A5 wr, wz, nr
        sub $0A5, $15A
        sub $0A5, $15A wz
        sub $0A5, $15A wc
        sub $0A5, $15A wr
        sub $0A5, $15A nr
        sub $0A5, $15A wz, wc
        sub $0A5, $15A wz, wr
        sub $0A5, $15A wz, nr
        sub $0A5, $15A wc, wr
        sub $0A5, $15A wc, nr
        sub $0A5, $15A wr, nr
        sub $0A5, $15A wz, wc, wr
        sub $0A5, $15A wz, wc, nr
        sub $0A5, $15A wz, wr, nr
        sub $0A5, $15A wc, wr, nr
        sub $0A5, $15A wz, wc, wr, nr
        sub $0A5, $15A nr, wr
        sub $0A5, $15A wc, nr, wz
        sub $0A5, $15A wr, wz, nr
        sub $15A, #$0A5
        sub $15A, #$0A5 wz
        sub $15A, #$0A5 wc
        sub $15A, #$0A5 wr
        sub $15A, #$0A5 nr
        sub $15A, #$0A5 wz, wc
        sub $15A, #$0A5 wz, wr
        sub $15A, #$0A5 wz, nr
        sub $15A, #$0A5 wc, wr
        sub $15A, #$0A5 wc, nr
        sub $15A, #$0A5 wr, nr
        sub $15A, #$0A5 wz, wc, wr
        sub $15A, #$0A5 wz, wc, nr
        sub $15A, #$0A5 wz, wr, nr
        sub $15A, #$0A5 wc, wr, nr
        sub $15A, #$0A5 wz, wc, wr, nr
        sub $15A, #$0A5 nr, wr
        sub $15A, #$0A5 wc, nr, wz
        sub $15A, #$0A5 wr, wz, nr
        addabs $0A5, $15A
        addabs $0A5, $15A wz
        addabs $0A5, $15A wc
        addabs $0A5, $15A wr
        addabs $0A5, $15A nr
        addabs $0A5, $15A wz, wc
        addabs $0A5, $15A wz, wr
        addabs $0A5, $15A wz, nr
        addabs $0A5, $15A wc, wr
        addabs $0A5, $15A wc, nr
        addabs $0A5, $15A wr, nr
        addabs $0A5, $15A wz, wc, wr
        addabs $0A5, $15A wz, wc, nr
        addabs $0A5, $15A wz, wr, nr
        addabs $0A5, $15A wc, wr, nr
        addabs $0A5, $15A wz, wc, wr, nr
        addabs $0A5, $15A nr, wr
        addabs $0A5, $15A wc, nr, wz
        addabs $0A5, $15A wr, wz, nr
        addabs $15A, #$0A5
        addabs $15A, #$0A5 wz
        addabs $15A, #$0A5 wc
        addabs $15A, #$0A5 wr
        addabs $15A, #$0A5 nr
        addabs $15A, #$0A5 wz, wc
        addabs $15A, #$0A5 wz, wr
        addabs $15A, #$0A5 wz, nr
        addabs $15A, #$0A5 wc, wr
        addabs $15A, #$0A5 wc, nr
        addabs $15A, #$0A5 wr, nr
        addabs $15A, #$0A5 wz, wc, wr
        addabs $15A, #$0A5 wz, wc, nr
        addabs $15A, #$0A5 wz, wr, nr
        addabs $15A, #$0A5 wc, wr, nr
        addabs $15A, #$0A5 wz, wc, wr, nr
        addabs $15A, #$0A5 nr, wr
        addabs $15A, #$0A5 wc, nr, wz
        addabs $15A, #$0A5 wr, wz, nr
        subabs $0A5, $15A
        subabs $0A5, $15A wz
        subabs $0A5, $15A wc
        subabs $0A5, $15A wr
        subabs $0A5, $15A nr
        subabs $0A5, $15A wz, wc
        subabs $0A5, $15A wz, wr
        subabs $0A5, $15A wz, nr
        subabs $0A5, $15A wc, wr
        subabs $0A5, $15A wc, nr
        subabs $0A5, $15A wr, nr
        subabs $0A5, $15A wz, wc, wr
        subabs $0A5, $15A wz, wc, nr
        subabs $0A5, $15A wz, wr, nr
        subabs $0A5, $15A wc, wr, nr
        subabs $0A5, $15A wz, wc, wr, nr
        subabs $0A5, $15A nr, wr
        subabs $0A5, $15A wc, nr, wz
        subabs $0A5, $15A wr, wz, nr
        subabs $15A, #$0A5
        subabs $15A, #$0A5 wz
        subabs $15A, #$0A5 wc
        subabs $15A, #$0A5 wr
        subabs $15A, #$0A5 nr
        subabs $15A, #$0A5 wz, wc
        subabs $15A, #$0A5 wz, wr
        subabs $15A, #$0A5 wz, nr
        subabs $15A, #$0A5 wc, wr
        subabs $15A, #$0A5 wc, nr
        subabs $15A, #$0A5 wr, nr
        subabs $15A, #$0A5 wz, wc, wr
        subabs $15A, #$0A5 wz, wc, nr
        subabs $15A, #$0A5 wz, wr, nr
        subabs $15A, #$0A5 wc, wr, nr
        subabs $15A, #$0A5 wz, wc, wr, nr
        subabs $15A, #$0A5 nr, wr
        subabs $15A, #$0A5 wc, nr, wz
        subabs $15A, #$0A5 wr, wz, nr
        sumc $0A5, $15A
        sumc $0A5, $15A wz
        sumc $0A5, $15A wc
        sumc $0A5, $15A wr
        sumc $0A5, $15A nr
        sumc $0A5, $15A wz, wc
        sumc $0A5, $15A wz, wr
        sumc $0A5, $15A wz, nr
        sumc $0A5, $15A wc, wr
        sumc $0A5, $15A wc, nr
        sumc $0A5, $15A wr, nr
        sumc $0A5, $15A wz, wc, wr
        sumc $0A5, $15A wz, wc, nr
        sumc $0A5, $15A wz, wr, nr
        sumc $0A5, $15A wc, wr, nr
        sumc $0A5, $15A wz, wc, wr, nr
        sumc $0A5, $15A nr, wr
        sumc $0A5, $15A wc, nr, wz
        sumc $0A5, $15A wr, wz, nr
        sumc $15A, #$0A5
        sumc $15A, #$0A5 wz
        sumc $15A, #$0A5 wc
        sumc $15A, #$0A5 wr
        sumc $15A, #$0A5 nr
        sumc $15A, #$0A5 wz, wc
        sumc $15A, #$0A5 wz, wr
        sumc $15A, #$0A5 wz, nr
        sumc $15A, #$0A5 wc, wr
        sumc $15A, #$0A5 wc, nr
        sumc $15A, #$0A5 wr, nr
        sumc $15A, #$0A5 wz, wc, wr
        sumc $15A, #$0A5 wz, wc, nr
        sumc $15A, #$0A5 wz, wr, nr
        sumc $15A, #$0A5 wc, wr, nr
        sumc $15A, #$0A5 wz, wc, wr, nr
        sumc $15A, #$0A5 nr, wr
        sumc $15A, #$0A5 wc, nr, wz
        sumc $15A, #$0A5 wr, wz, nr
        sumnc $0A5, $15A
        sumnc $0A5, $15A wz
        sumnc $0A5, $15A wc
        sumnc $0A5, $15A wr
        sumnc $0A5, $15A nr
        sumnc $0A5, $15A wz, wc
        org 0
        sumnc $0A5, $15A wz, wr
        sumnc $0A5, $15A wz, nr
        sumnc $0A5, $15A wc, wr
        sumnc $0A5, $15A wc, nr
        sumnc $0A5, $15A wr, nr
        sumnc $0A5, $15A wz, wc, wr
        sumnc $0A5, $15A wz, wc, nr
        sumnc $0A5, $15A wz, wr, nr
        sumnc $0A5, $15A wc, wr, nr
        sumnc $0A5, $15A wz, wc, wr, nr
        sumnc $0A5, $15A nr, wr
        sumnc $0A5, $15A wc, nr, wz
        sumnc $0A5, $15A wr, wz, nr
        sumnc $15A, #$0A5
        sumnc $15A, #$0A5 wz
        sumnc $15A, #$0A5 wc
        sumnc $15A, #$0A5 wr
        sumnc $15A, #$0A5 nr
        sumnc $15A, #$0A5 wz, wc
        sumnc $15A, #$0A5 wz, wr
        sumnc $15A, #$0A5 wz, nr
        sumnc $15A, #$0A5 wc, wr
        sumnc $15A, #$0A5 wc, nr
        sumnc $15A, #$0A5 wr, nr
        sumnc $15A, #$0A5 wz, wc, wr
        sumnc $15A, #$0A5 wz, wc, nr
        sumnc $15A, #$0A5 wz, wr, nr
        sumnc $15A, #$0A5 wc, wr, nr
        sumnc $15A, #$0A5 wz, wc, wr, nr
        sumnc $15A, #$0A5 nr, wr
        sumnc $15A, #$0A5 wc, nr, wz
        sumnc $15A, #$0A5 wr, wz, nr
        sumz $0A5, $15A
        sumz $0A5, $15A wz
        sumz $0A5, $15A wc
        sumz $0A5, $15A wr
        sumz $0A5, $15A nr
        sumz $0A5, $15A wz, wc
        sumz $0A5, $15A wz, wr
        sumz $0A5, $15A wz, nr
        sumz $0A5, $15A wc, wr
        sumz $0A5, $15A wc, nr
        sumz $0A5, $15A wr, nr
        sumz $0A5, $15A wz, wc, wr
        sumz $0A5, $15A wz, wc, nr
        sumz $0A5, $15A wz, wr, nr
        sumz $0A5, $15A wc, wr, nr
        sumz $0A5, $15A wz, wc, wr, nr
        sumz $0A5, $15A nr, wr
        sumz $0A5, $15A wc, nr, wz
        sumz $0A5, $15A wr, wz, nr
        sumz $15A, #$0A5
        sumz $15A, #$0A5 wz
        sumz $15A, #$0A5 wc
        sumz $15A, #$0A5 wr
        sumz $15A, #$0A5 nr
        sumz $15A, #$0A5 wz, wc
        sumz $15A, #$0A5 wz, wr
        sumz $15A, #$0A5 wz, nr
        sumz $15A, #$0A5 wc, wr
        sumz $15A, #$0A5 wc, nr
        sumz $15A, #$0A5 wr, nr
        sumz $15A, #$0A5 wz, wc, wr
        sumz $15A, #$0A5 wz, wc, nr
        sumz $15A, #$0A5 wz, wr, nr
        sumz $15A, #$0A5 wc, wr, nr
        sumz $15A, #$0A5 wz, wc, wr, nr
        sumz $15A, #$0A5 nr, wr
        sumz $15A, #$0A5 wc, nr, wz
        sumz $15A, #$0A5 wr, wz, nr
        sumnz $0A5, $15A
        sumnz $0A5, $15A wz
        sumnz $0A5, $15A wc
        sumnz $0A5, $15A wr
        sumnz $0A5, $15A nr
        sumnz $0A5, $15A wz, wc
        sumnz $0A5, $15A wz, wr
        sumnz $0A5, $15A wz, nr
        sumnz $0A5, $15A wc, wr
        sumnz $0A5, $15A wc, nr
        sumnz $0A5, $15A wr, nr
        sumnz $0A5, $15A wz, wc, wr
        sumnz $0A5, $15A wz, wc, nr
        sumnz $0A5, $15A wz, wr, nr
        sumnz $0A5, $15A wc, wr, nr
        sumnz $0A5, $15A wz, wc, wr, nr
        sumnz $0A5, $15A nr, wr
        sumnz $0A5, $15A wc, nr, wz
        sumnz $0A5, $15A wr, wz, nr
        sumnz $15A, #$0A5
        sumnz $15A, #$0A5 wz
        sumnz $15A, #$0A5 wc
        sumnz $15A, #$0A5 wr
        sumnz $15A, #$0A5 nr
        sumnz $15A, #$0A5 wz, wc
        sumnz $15A, #$0A5 wz, wr
        sumnz $15A, #$0A5 wz, nr
        sumnz $15A, #$0A5 wc, wr
        sumnz $15A, #$0A5 wc, nr
        sumnz $15A, #$0A5 wr, nr
        sumnz $15A, #$0A5 wz, wc, wr
        sumnz $15A, #$0A5 wz, wc, nr
        sumnz $15A, #$0A5 wz, wr, nr
        sumnz $15A, #$0A5 wc, wr, nr
        sumnz $15A, #$0A5 wz, wc, wr, nr
        sumnz $15A, #$0A5 nr, wr
        sumnz $15A, #$0A5 wc, nr, wz
        sumnz $15A, #$0A5 wr, wz, nr
        mov $0A5, $15A
        mov $0A5, $15A wz
        mov $0A5, $15A wc
        mov $0A5, $15A wr
        mov $0A5, $15A nr
        mov $0A5, $15A wz, wc
        mov $0A5, $15A wz, wr
        mov $0A5, $15A wz, nr
        mov $0A5, $15A wc, wr
        mov $0A5, $15A wc, nr
        mov $0A5, $15A wr, nr
        mov $0A5, $15A wz, wc, wr
        mov $0A5, $15A wz, wc, nr
        mov $0A5, $15A wz, wr, nr
        mov $0A5, $15A wc, wr, nr
        mov $0A5, $15A wz, wc, wr, nr
        mov $0A5, $15A nr, wr
        mov $0A5, $15A wc, nr, wz
        mov $0A5, $15A wr, wz, nr
        mov $15A, #$0A5
        mov $15A, #$0A5 wz
        mov $15A, #$0A5 wc
        mov $15A, #$0A5 wr
        mov $15A, #$0A5 nr
        mov $15A, #$0A5 wz, wc
        mov $15A, #$0A5 wz, wr
        mov $15A, #$0A5 wz, nr
        mov $15A, #$0A5 wc, wr
        mov $15A, #$0A5 wc, nr
        mov $15A, #$0A5 wr, nr
        mov $15A, #$0A5 wz, wc, wr
        mov $15A, #$0A5 wz, wc, nr
        mov $15A, #$0A5 wz, wr, nr
        mov $15A, #$0A5 wc, wr, nr
        mov $15A, #$0A5 wz, wc, wr, nr
        mov $15A, #$0A5 nr, wr
        mov $15A, #$0A5 wc, nr, wz
        mov $15A, #$0A5 wr, wz, nr
        neg $0A5, $15A
        neg $0A5, $15A wz
        neg $0A5, $15A wc
        neg $0A5, $15A wr
        neg $0A5, $15A nr
        neg $0A5, $15A wz, wc
        neg $0A5, $15A wz, wr
        neg $0A5, $15A wz, nr
        neg $0A5, $15A wc, wr
        neg $0A5, $15A wc, nr
        neg $0A5, $15A wr, nr
        neg $0A5, $15A wz, wc, wr
        neg $0A5, $15A wz, wc, nr
        neg $0A5, $15A wz, wr, nr
        neg $0A5, $15A wc, wr, nr
        neg $0A5, $15A wz, wc, wr, nr
        neg $0A5, $15A nr, wr
        neg $0A5, $15A wc, nr, wz
        neg $0A5, $15A wr, wz, nr
        neg $15A, #$0A5
        neg $15A, #$0A5 wz
        neg $15A, #$0A5 wc
        neg $15A, #$0A5 wr
        neg $15A, #$0A5 nr
        neg $15A, #$0A5 wz, wc
        neg $15A, #$0A5 wz, wr
        neg $15A, #$0A5 wz, nr
        neg $15A, #$0A5 wc, wr
        neg $15A, #$0A5 wc, nr
        neg $15A, #$0A5 wr, nr
        neg $15A, #$0A5 wz, wc, wr
        neg $15A, #$0A5 wz, wc, nr
        neg $15A, #$0A5 wz, wr, nr
        neg $15A, #$0A5 wc, wr, nr
        neg $15A, #$0A5 wz, wc, wr, nr
        neg $15A, #$0A5 nr, wr
        neg $15A, #$0A5 wc, nr, wz
        neg $15A, #$0A5 wr, wz, nr
        abs $0A5, $15A
        abs $0A5, $15A wz
        abs $0A5, $15A wc
        abs $0A5, $15A wr
        abs $0A5, $15A nr
        abs $0A5, $15A wz, wc
        abs $0A5, $15A wz, wr
        abs $0A5, $15A wz, nr
        abs $0A5, $15A wc, wr
        abs $0A5, $15A wc, nr
        abs $0A5, $15A wr, nr
        abs $0A5, $15A wz, wc, wr
        abs $0A5, $15A wz, wc, nr
        abs $0A5, $15A wz, wr, nr
        abs $0A5, $15A wc, wr, nr
        abs $0A5, $15A wz, wc, wr, nr
        abs $0A5, $15A nr, wr
        abs $0A5, $15A wc, nr, wz
        abs $0A5, $15A wr, wz, nr
        abs $15A, #$0A5
        abs $15A, #$0A5 wz
        abs $15A, #$0A5 wc
        abs $15A, #$0A5 wr
        abs $15A, #$0A5 nr
        abs $15A, #$0A5 wz, wc
        abs $15A, #$0A5 wz, wr
        abs $15A, #$0A5 wz, nr
        abs $15A, #$0A5 wc, wr
        abs $15A, #$0A5 wc, nr
        abs $15A, #$0A5 wr, nr
        abs $15A, #$0A5 wz, wc, wr
        abs $15A, #$0A5 wz, wc, nr
        abs $15A, #$0A5 wz, wr, nr
        abs $15A, #$0A5 wc, wr, nr
        abs $15A, #$0A5 wz, wc, wr, nr
        abs $15A, #$0A5 nr, wr
        abs $15A, #$0A5 wc, nr, wz
        abs $15A, #$0A5 wr, wz, nr
        absneg $0A5, $15A
        absneg $0A5, $15A wz
        absneg $0A5, $15A wc
        absneg $0A5, $15A wr
        absneg $0A5, $15A nr
        absneg $0A5, $15A wz, wc
        absneg $0A5, $15A wz, wr
        absneg $0A5, $15A wz, nr
        absneg $0A5, $15A wc, wr
        absneg $0A5, $15A wc, nr
        absneg $0A5, $15A wr, nr
        absneg $0A5, $15A wz, wc, wr
        absneg $0A5, $15A wz, wc, nr
        absneg $0A5, $15A wz, wr, nr
        absneg $0A5, $15A wc, wr, nr
        absneg $0A5, $15A wz, wc, wr, nr
        absneg $0A5, $15A nr, wr
        absneg $0A5, $15A wc, nr, wz
        absneg $0A5, $15A wr, wz, nr
        absneg $15A, #$0A5
        absneg $15A, #$0A5 wz
        absneg $15A, #$0A5 wc
        absneg $15A, #$0A5 wr
        absneg $15A, #$0A5 nr
        absneg $15A, #$0A5 wz, wc
        absneg $15A, #$0A5 wz, wr
        absneg $15A, #$0A5 wz, nr
        absneg $15A, #$0A5 wc, wr
        absneg $15A, #$0A5 wc, nr
        absneg $15A, #$0A5 wr, nr
        absneg $15A, #$0A5 wz, wc, wr
        absneg $15A, #$0A5 wz, wc, nr
        absneg $15A, #$0A5 wz, wr, nr
        absneg $15A, #$0A5 wc, wr, nr
        org 0
        absneg $15A, #$0A5 wz, wc, wr, nr
        absneg $15A, #$0A5 nr, wr
        absneg $15A, #$0A5 wc, nr, wz
        absneg $15A, #$0A5 wr, wz, nr
        negc $0A5, $15A
        negc $0A5, $15A wz
        negc $0A5, $15A wc
        negc $0A5, $15A wr
        negc $0A5, $15A nr
        negc $0A5, $15A wz, wc
        negc $0A5, $15A wz, wr
        negc $0A5, $15A wz, nr
        negc $0A5, $15A wc, wr
        negc $0A5, $15A wc, nr
        negc $0A5, $15A wr, nr
        negc $0A5, $15A wz, wc, wr
        negc $0A5, $15A wz, wc, nr
        negc $0A5, $15A wz, wr, nr
        negc $0A5, $15A wc, wr, nr
        negc $0A5, $15A wz, wc, wr, nr
        negc $0A5, $15A nr, wr
        negc $0A5, $15A wc, nr, wz
        negc $0A5, $15A wr, wz, nr
        negc $15A, #$0A5
        negc $15A, #$0A5 wz
        negc $15A, #$0A5 wc
        negc $15A, #$0A5 wr
        negc $15A, #$0A5 nr
        negc $15A, #$0A5 wz, wc
        negc $15A, #$0A5 wz, wr
        negc $15A, #$0A5 wz, nr
        negc $15A, #$0A5 wc, wr
        negc $15A, #$0A5 wc, nr
        negc $15A, #$0A5 wr, nr
        negc $15A, #$0A5 wz, wc, wr
        negc $15A, #$0A5 wz, wc, nr
        negc $15A, #$0A5 wz, wr, nr
        negc $15A, #$0A5 wc, wr, nr
        negc $15A, #$0A5 wz, wc, wr, nr
        negc $15A, #$0A5 nr, wr
        negc $15A, #$0A5 wc, nr, wz
        negc $15A, #$0A5 wr, wz, nr
        negnc $0A5, $15A
        negnc $0A5, $15A wz
        negnc $0A5, $15A wc
        negnc $0A5, $15A wr
        negnc $0A5, $15A nr
        negnc $0A5, $15A wz, wc
        negnc $0A5, $15A wz, wr
        negnc $0A5, $15A wz, nr
        negnc $0A5, $15A wc, wr
        negnc $0A5, $15A wc, nr
        negnc $0A5, $15A wr, nr
        negnc $0A5, $15A wz, wc, wr
        negnc $0A5, $15A wz, wc, nr
        negnc $0A5, $15A wz, wr, nr
        negnc $0A5, $15A wc, wr, nr
        negnc $0A5, $15A wz, wc, wr, nr
        negnc $0A5, $15A nr, wr
        negnc $0A5, $15A wc, nr, wz
        negnc $0A5, $15A wr, wz, nr
        negnc $15A, #$0A5
        negnc $15A, #$0A5 wz
        negnc $15A, #$0A5 wc
        negnc $15A, #$0A5 wr
        negnc $15A, #$0A5 nr
        negnc $15A, #$0A5 wz, wc
        negnc $15A, #$0A5 wz, wr
        negnc $15A, #$0A5 wz, nr
        negnc $15A, #$0A5 wc, wr
        negnc $15A, #$0A5 wc, nr
        negnc $15A, #$0A5 wr, nr
        negnc $15A, #$0A5 wz, wc, wr
        negnc $15A, #$0A5 wz, wc, nr
        negnc $15A, #$0A5 wz, wr, nr
        negnc $15A, #$0A5 wc, wr, nr
        negnc $15A, #$0A5 wz, wc, wr, nr
        negnc $15A, #$0A5 nr, wr
        negnc $15A, #$0A5 wc, nr, wz
        negnc $15A, #$0A5 wr, wz, nr
        negz $0A5, $15A
        negz $0A5, $15A wz
        negz $0A5, $15A wc
        negz $0A5, $15A wr
        negz $0A5, $15A nr
        negz $0A5, $15A wz, wc
        negz $0A5, $15A wz, wr
        negz $0A5, $15A wz, nr
        negz $0A5, $15A wc, wr
        negz $0A5, $15A wc, nr
        negz $0A5, $15A wr, nr
        negz $0A5, $15A wz, wc, wr
        negz $0A5, $15A wz, wc, nr
        negz $0A5, $15A wz, wr, nr
        negz $0A5, $15A wc, wr, nr
        negz $0A5, $15A wz, wc, wr, nr
        negz $0A5, $15A nr, wr
        negz $0A5, $15A wc, nr, wz
        negz $0A5, $15A wr, wz, nr
        negz $15A, #$0A5
        negz $15A, #$0A5 wz
        negz $15A, #$0A5 wc
        negz $15A, #$0A5 wr
        negz $15A, #$0A5 nr
        negz $15A, #$0A5 wz, wc
        negz $15A, #$0A5 wz, wr
        negz $15A, #$0A5 wz, nr
        negz $15A, #$0A5 wc, wr
        negz $15A, #$0A5 wc, nr
        negz $15A, #$0A5 wr, nr
        negz $15A, #$0A5 wz, wc, wr
        negz $15A, #$0A5 wz, wc, nr
        negz $15A, #$0A5 wz, wr, nr
        negz $15A, #$0A5 wc, wr, nr
        negz $15A, #$0A5 wz, wc, wr, nr
        negz $15A, #$0A5 nr, wr
        negz $15A, #$0A5 wc, nr, wz
        negz $15A, #$0A5 wr, wz, nr
        negnz $0A5, $15A
        negnz $0A5, $15A wz
        negnz $0A5, $15A wc
        negnz $0A5, $15A wr
        negnz $0A5, $15A nr
        negnz $0A5, $15A wz, wc
        negnz $0A5, $15A wz, wr
        negnz $0A5, $15A wz, nr
        negnz $0A5, $15A wc, wr
        negnz $0A5, $15A wc, nr
        negnz $0A5, $15A wr, nr
        negnz $0A5, $15A wz, wc, wr
        negnz $0A5, $15A wz, wc, nr
        negnz $0A5, $15A wz, wr, nr
        negnz $0A5, $15A wc, wr, nr
        negnz $0A5, $15A wz, wc, wr, nr
        negnz $0A5, $15A nr, wr
        negnz $0A5, $15A wc, nr, wz
        negnz $0A5, $15A wr, wz, nr
        negnz $15A, #$0A5
        negnz $15A, #$0A5 wz
        negnz $15A, #$0A5 wc
        negnz $15A, #$0A5 wr
        negnz $15A, #$0A5 nr
        negnz $15A, #$0A5 wz, wc
        negnz $15A, #$0A5 wz, wr
        negnz $15A, #$0A5 wz, nr
        negnz $15A, #$0A5 wc, wr
        negnz $15A, #$0A5 wc, nr
        negnz $15A, #$0A5 wr, nr
        negnz $15A, #$0A5 wz, wc, wr
        negnz $15A, #$0A5 wz, wc, nr
        negnz $15A, #$0A5 wz, wr, nr
        negnz $15A, #$0A5 wc, wr, nr
        negnz $15A, #$0A5 wz, wc, wr, nr
        negnz $15A, #$0A5 nr, wr
        negnz $15A, #$0A5 wc, nr, wz
        negnz $15A, #$0A5 wr, wz, nr
        cmps $0A5, $15A
        cmps $0A5, $15A wz
        cmps $0A5, $15A wc
        cmps $0A5, $15A wr
        cmps $0A5, $15A nr
        cmps $0A5, $15A wz, wc
        cmps $0A5, $15A wz, wr
        cmps $0A5, $15A wz, nr
        cmps $0A5, $15A wc, wr
        cmps $0A5, $15A wc, nr
        cmps $0A5, $15A wr, nr
        cmps $0A5, $15A wz, wc, wr
        cmps $0A5, $15A wz, wc, nr
        cmps $0A5, $15A wz, wr, nr
        cmps $0A5, $15A wc, wr, nr
        cmps $0A5, $15A wz, wc, wr, nr
        cmps $0A5, $15A nr, wr
        cmps $0A5, $15A wc, nr, wz
        cmps $0A5, $15A wr, wz, nr
        cmps $15A, #$0A5
        cmps $15A, #$0A5 wz
        cmps $15A, #$0A5 wc
        cmps $15A, #$0A5 wr
        cmps $15A, #$0A5 nr
        cmps $15A, #$0A5 wz, wc
        cmps $15A, #$0A5 wz, wr
        cmps $15A, #$0A5 wz, nr
        cmps $15A, #$0A5 wc, wr
        cmps $15A, #$0A5 wc, nr
        cmps $15A, #$0A5 wr, nr
        cmps $15A, #$0A5 wz, wc, wr
        cmps $15A, #$0A5 wz, wc, nr
        cmps $15A, #$0A5 wz, wr, nr
        cmps $15A, #$0A5 wc, wr, nr
        cmps $15A, #$0A5 wz, wc, wr, nr
        cmps $15A, #$0A5 nr, wr
        cmps $15A, #$0A5 wc, nr, wz
        cmps $15A, #$0A5 wr, wz, nr
        cmpsx $0A5, $15A
        cmpsx $0A5, $15A wz
        cmpsx $0A5, $15A wc
        cmpsx $0A5, $15A wr
        cmpsx $0A5, $15A nr
        cmpsx $0A5, $15A wz, wc
        cmpsx $0A5, $15A wz, wr
        cmpsx $0A5, $15A wz, nr
        cmpsx $0A5, $15A wc, wr
        cmpsx $0A5, $15A wc, nr
        cmpsx $0A5, $15A wr, nr
        cmpsx $0A5, $15A wz, wc, wr
        cmpsx $0A5, $15A wz, wc, nr
        cmpsx $0A5, $15A wz, wr, nr
        cmpsx $0A5, $15A wc, wr, nr
        cmpsx $0A5, $15A wz, wc, wr, nr
        cmpsx $0A5, $15A nr, wr
        cmpsx $0A5, $15A wc, nr, wz
        cmpsx $0A5, $15A wr, wz, nr
        cmpsx $15A, #$0A5
        cmpsx $15A, #$0A5 wz
        cmpsx $15A, #$0A5 wc
        cmpsx $15A, #$0A5 wr
        cmpsx $15A, #$0A5 nr
        cmpsx $15A, #$0A5 wz, wc
        cmpsx $15A, #$0A5 wz, wr
        cmpsx $15A, #$0A5 wz, nr
        cmpsx $15A, #$0A5 wc, wr
        cmpsx $15A, #$0A5 wc, nr
        cmpsx $15A, #$0A5 wr, nr
        cmpsx $15A, #$0A5 wz, wc, wr
        cmpsx $15A, #$0A5 wz, wc, nr
        cmpsx $15A, #$0A5 wz, wr, nr
        cmpsx $15A, #$0A5 wc, wr, nr
        cmpsx $15A, #$0A5 wz, wc, wr, nr
        cmpsx $15A, #$0A5 nr, wr
        cmpsx $15A, #$0A5 wc, nr, wz
        cmpsx $15A, #$0A5 wr, wz, nr
        addx $0A5, $15A
        addx $0A5, $15A wz
        addx $0A5, $15A wc
        addx $0A5, $15A wr
        addx $0A5, $15A nr
        addx $0A5, $15A wz, wc
        addx $0A5, $15A wz, wr
        addx $0A5, $15A wz, nr
        addx $0A5, $15A wc, wr
        addx $0A5, $15A wc, nr
        addx $0A5, $15A wr, nr
        addx $0A5, $15A wz, wc, wr
        addx $0A5, $15A wz, wc, nr
        addx $0A5, $15A wz, wr, nr
        addx $0A5, $15A wc, wr, nr
        addx $0A5, $15A wz, wc, wr, nr
        addx $0A5, $15A nr, wr
        addx $0A5, $15A wc, nr, wz
        addx $0A5, $15A wr, wz, nr
        addx $15A, #$0A5
        addx $15A, #$0A5 wz
        addx $15A, #$0A5 wc
        addx $15A, #$0A5 wr
        addx $15A, #$0A5 nr
        org 0
        addx $15A, #$0A5 wz, wc
        addx $15A, #$0A5 wz, wr
        addx $15A, #$0A5 wz, nr
        addx $15A, #$0A5 wc, wr
        addx $15A, #$0A5 wc, nr
        addx $15A, #$0A5 wr, nr
        addx $15A, #$0A5 wz, wc, wr
        addx $15A, #$0A5 wz, wc, nr
        addx $15A, #$0A5 wz, wr, nr
        addx $15A, #$0A5 wc, wr, nr
        addx $15A, #$0A5 wz, wc, wr, nr
        addx $15A, #$0A5 nr, wr
        addx $15A, #$0A5 wc, nr, wz
        addx $15A, #$0A5 wr, wz, nr
        cmpx $0A5, $15A
        cmpx $0A5, $15A wz
        cmpx $0A5, $15A wc
        cmpx $0A5, $15A wr
        cmpx $0A5, $15A nr
        cmpx $0A5, $15A wz, wc
        cmpx $0A5, $15A wz, wr
        cmpx $0A5, $15A wz, nr
        cmpx $0A5, $15A wc, wr
        cmpx $0A5, $15A wc, nr
        cmpx $0A5, $15A wr, nr
        cmpx $0A5, $15A wz, wc, wr
        cmpx $0A5, $15A wz, wc, nr
        cmpx $0A5, $15A wz, wr, nr
        cmpx $0A5, $15A wc, wr, nr
        cmpx $0A5, $15A wz, wc, wr, nr
        cmpx $0A5, $15A nr, wr
        cmpx $0A5, $15A wc, nr, wz
        cmpx $0A5, $15A wr, wz, nr
        cmpx $15A, #$0A5
        cmpx $15A, #$0A5 wz
        cmpx $15A, #$0A5 wc
        cmpx $15A, #$0A5 wr
        cmpx $15A, #$0A5 nr
        cmpx $15A, #$0A5 wz, wc
        cmpx $15A, #$0A5 wz, wr
        cmpx $15A, #$0A5 wz, nr
        cmpx $15A, #$0A5 wc, wr
        cmpx $15A, #$0A5 wc, nr
        cmpx $15A, #$0A5 wr, nr
        cmpx $15A, #$0A5 wz, wc, wr
        cmpx $15A, #$0A5 wz, wc, nr
        cmpx $15A, #$0A5 wz, wr, nr
        cmpx $15A, #$0A5 wc, wr, nr
        cmpx $15A, #$0A5 wz, wc, wr, nr
        cmpx $15A, #$0A5 nr, wr
        cmpx $15A, #$0A5 wc, nr, wz
        cmpx $15A, #$0A5 wr, wz, nr
        subx $0A5, $15A
        subx $0A5, $15A wz
        subx $0A5, $15A wc
        subx $0A5, $15A wr
        subx $0A5, $15A nr
        subx $0A5, $15A wz, wc
        subx $0A5, $15A wz, wr
        subx $0A5, $15A wz, nr
        subx $0A5, $15A wc, wr
        subx $0A5, $15A wc, nr
        subx $0A5, $15A wr, nr
        subx $0A5, $15A wz, wc, wr
        subx $0A5, $15A wz, wc, nr
        subx $0A5, $15A wz, wr, nr
        subx $0A5, $15A wc, wr, nr
        subx $0A5, $15A wz, wc, wr, nr
        subx $0A5, $15A nr, wr
        subx $0A5, $15A wc, nr, wz
        subx $0A5, $15A wr, wz, nr
        subx $15A, #$0A5
        subx $15A, #$0A5 wz
        subx $15A, #$0A5 wc
        subx $15A, #$0A5 wr
        subx $15A, #$0A5 nr
        subx $15A, #$0A5 wz, wc
        subx $15A, #$0A5 wz, wr
        subx $15A, #$0A5 wz, nr
        subx $15A, #$0A5 wc, wr
        subx $15A, #$0A5 wc, nr
        subx $15A, #$0A5 wr, nr
        subx $15A, #$0A5 wz, wc, wr
        subx $15A, #$0A5 wz, wc, nr
        subx $15A, #$0A5 wz, wr, nr
        subx $15A, #$0A5 wc, wr, nr
        subx $15A, #$0A5 wz, wc, wr, nr
        subx $15A, #$0A5 nr, wr
        subx $15A, #$0A5 wc, nr, wz
        subx $15A, #$0A5 wr, wz, nr
        adds $0A5, $15A
        adds $0A5, $15A wz
        adds $0A5, $15A wc
        adds $0A5, $15A wr
        adds $0A5, $15A nr
        adds $0A5, $15A wz, wc
        adds $0A5, $15A wz, wr
        adds $0A5, $15A wz, nr
        adds $0A5, $15A wc, wr
        adds $0A5, $15A wc, nr
        adds $0A5, $15A wr, nr
        adds $0A5, $15A wz, wc, wr
        adds $0A5, $15A wz, wc, nr
        adds $0A5, $15A wz, wr, nr
        adds $0A5, $15A wc, wr, nr
        adds $0A5, $15A wz, wc, wr, nr
        adds $0A5, $15A nr, wr
        adds $0A5, $15A wc, nr, wz
        adds $0A5, $15A wr, wz, nr
        adds $15A, #$0A5
        adds $15A, #$0A5 wz
        adds $15A, #$0A5 wc
        adds $15A, #$0A5 wr
        adds $15A, #$0A5 nr
        adds $15A, #$0A5 wz, wc
        adds $15A, #$0A5 wz, wr
        adds $15A, #$0A5 wz, nr
        adds $15A, #$0A5 wc, wr
        adds $15A, #$0A5 wc, nr
        adds $15A, #$0A5 wr, nr
        adds $15A, #$0A5 wz, wc, wr
        adds $15A, #$0A5 wz, wc, nr
        adds $15A, #$0A5 wz, wr, nr
        adds $15A, #$0A5 wc, wr, nr
        adds $15A, #$0A5 wz, wc, wr, nr
        adds $15A, #$0A5 nr, wr
        adds $15A, #$0A5 wc, nr, wz
        adds $15A, #$0A5 wr, wz, nr
        subs $0A5, $15A
        subs $0A5, $15A wz
        subs $0A5, $15A wc
        subs $0A5, $15A wr
        subs $0A5, $15A nr
        subs $0A5, $15A wz, wc
        subs $0A5, $15A wz, wr
        subs $0A5, $15A wz, nr
        subs $0A5, $15A wc, wr
        subs $0A5, $15A wc, nr
        subs $0A5, $15A wr, nr
        subs $0A5, $15A wz, wc, wr
        subs $0A5, $15A wz, wc, nr
        subs $0A5, $15A wz, wr, nr
        subs $0A5, $15A wc, wr, nr
        subs $0A5, $15A wz, wc, wr, nr
        subs $0A5, $15A nr, wr
        subs $0A5, $15A wc, nr, wz
        subs $0A5, $15A wr, wz, nr
        subs $15A, #$0A5
        subs $15A, #$0A5 wz
        subs $15A, #$0A5 wc
        subs $15A, #$0A5 wr
        subs $15A, #$0A5 nr
        subs $15A, #$0A5 wz, wc
        subs $15A, #$0A5 wz, wr
        subs $15A, #$0A5 wz, nr
        subs $15A, #$0A5 wc, wr
        subs $15A, #$0A5 wc, nr
        subs $15A, #$0A5 wr, nr
        subs $15A, #$0A5 wz, wc, wr
        subs $15A, #$0A5 wz, wc, nr
        subs $15A, #$0A5 wz, wr, nr
        subs $15A, #$0A5 wc, wr, nr
        subs $15A, #$0A5 wz, wc, wr, nr
        subs $15A, #$0A5 nr, wr
        subs $15A, #$0A5 wc, nr, wz
        subs $15A, #$0A5 wr, wz, nr
        addsx $0A5, $15A
        addsx $0A5, $15A wz
        addsx $0A5, $15A wc
        addsx $0A5, $15A wr
        addsx $0A5, $15A nr
        addsx $0A5, $15A wz, wc
        addsx $0A5, $15A wz, wr
        addsx $0A5, $15A wz, nr
        addsx $0A5, $15A wc, wr
        addsx $0A5, $15A wc, nr
        addsx $0A5, $15A wr, nr
        addsx $0A5, $15A wz, wc, wr
        addsx $0A5, $15A wz, wc, nr
        addsx $0A5, $15A wz, wr, nr
        addsx $0A5, $15A wc, wr, nr
        addsx $0A5, $15A wz, wc, wr, nr
        addsx $0A5, $15A nr, wr
        addsx $0A5, $15A wc, nr, wz
        addsx $0A5, $15A wr, wz, nr
        addsx $15A, #$0A5
        addsx $15A, #$0A5 wz
        addsx $15A, #$0A5 wc
        addsx $15A, #$0A5 wr
        addsx $15A, #$0A5 nr
        addsx $15A, #$0A5 wz, wc
        addsx $15A, #$0A5 wz, wr
        addsx $15A, #$0A5 wz, nr
        addsx $15A, #$0A5 wc, wr
        addsx $15A, #$0A5 wc, nr
        addsx $15A, #$0A5 wr, nr
        addsx $15A, #$0A5 wz, wc, wr
        addsx $15A, #$0A5 wz, wc, nr
        addsx $15A, #$0A5 wz, wr, nr
        addsx $15A, #$0A5 wc, wr, nr
        addsx $15A, #$0A5 wz, wc, wr, nr
        addsx $15A, #$0A5 nr, wr
        addsx $15A, #$0A5 wc, nr, wz
        addsx $15A, #$0A5 wr, wz, nr
        subsx $0A5, $15A
        subsx $0A5, $15A wz
        subsx $0A5, $15A wc
        subsx $0A5, $15A wr
        subsx $0A5, $15A nr
        subsx $0A5, $15A wz, wc
        subsx $0A5, $15A wz, wr
        subsx $0A5, $15A wz, nr
        subsx $0A5, $15A wc, wr
        subsx $0A5, $15A wc, nr
        subsx $0A5, $15A wr, nr
        subsx $0A5, $15A wz, wc, wr
        subsx $0A5, $15A wz, wc, nr
        subsx $0A5, $15A wz, wr, nr
        subsx $0A5, $15A wc, wr, nr
        subsx $0A5, $15A wz, wc, wr, nr
        subsx $0A5, $15A nr, wr
        subsx $0A5, $15A wc, nr, wz
        subsx $0A5, $15A wr, wz, nr
        subsx $15A, #$0A5
        subsx $15A, #$0A5 wz
        subsx $15A, #$0A5 wc
        subsx $15A, #$0A5 wr
        subsx $15A, #$0A5 nr
        subsx $15A, #$0A5 wz, wc
        subsx $15A, #$0A5 wz, wr
        subsx $15A, #$0A5 wz, nr
        subsx $15A, #$0A5 wc, wr
        subsx $15A, #$0A5 wc, nr
        subsx $15A, #$0A5 wr, nr
        subsx $15A, #$0A5 wz, wc, wr
        subsx $15A, #$0A5 wz, wc, nr
        subsx $15A, #$0A5 wz, wr, nr
        subsx $15A, #$0A5 wc, wr, nr
        subsx $15A, #$0A5 wz, wc, wr, nr
        subsx $15A, #$0A5 nr, wr
        subsx $15A, #$0A5 wc, nr, wz
        subsx $15A, #$0A5 wr, wz, nr
        cmpsub $0A5, $15A
        cmpsub $0A5, $15A wz
        cmpsub $0A5, $15A wc
        cmpsub $0A5, $15A wr
        cmpsub $0A5, $15A nr
        cmpsub $0A5, $15A wz, wc
        cmpsub $0A5, $15A wz, wr
        cmpsub $0A5, $15A wz, nr
        cmpsub $0A5, $15A wc, wr
        cmpsub $0A5, $15A wc, nr
        cmpsub $0A5, $15A wr, nr
        cmpsub $0A5, $15A wz, wc, wr
        cmpsub $0A5, $15A wz, wc, nr
        cmpsub $0A5, $15A wz, wr, nr
        org 0
        cmpsub $0A5, $15A wc, wr, nr
        cmpsub $0A5, $15A wz, wc, wr, nr
        cmpsub $0A5, $15A nr, wr
        cmpsub $0A5, $15A wc, nr, wz
        cmpsub $0A5, $15A wr, wz, nr
        cmpsub $15A, #$0A5
        cmpsub $15A, #$0A5 wz
        cmpsub $15A, #$0A5 wc
        cmpsub $15A, #$0A5 wr
        cmpsub $15A, #$0A5 nr
        cmpsub $15A, #$0A5 wz, wc
        cmpsub $15A, #$0A5 wz, wr
        cmpsub $15A, #$0A5 wz, nr
        cmpsub $15A, #$0A5 wc, wr
        cmpsub $15A, #$0A5 wc, nr
        cmpsub $15A, #$0A5 wr, nr
        cmpsub $15A, #$0A5 wz, wc, wr
        cmpsub $15A, #$0A5 wz, wc, nr
        cmpsub $15A, #$0A5 wz, wr, nr
        cmpsub $15A, #$0A5 wc, wr, nr
        cmpsub $15A, #$0A5 wz, wc, wr, nr
        cmpsub $15A, #$0A5 nr, wr
        cmpsub $15A, #$0A5 wc, nr, wz
        cmpsub $15A, #$0A5 wr, wz, nr
        djnz $0A5, $15A
        djnz $0A5, $15A wz
        djnz $0A5, $15A wc
        djnz $0A5, $15A wr
        djnz $0A5, $15A nr
        djnz $0A5, $15A wz, wc
        djnz $0A5, $15A wz, wr
        djnz $0A5, $15A wz, nr
        djnz $0A5, $15A wc, wr
        djnz $0A5, $15A wc, nr
        djnz $0A5, $15A wr, nr
        djnz $0A5, $15A wz, wc, wr
        djnz $0A5, $15A wz, wc, nr
        djnz $0A5, $15A wz, wr, nr
        djnz $0A5, $15A wc, wr, nr
        djnz $0A5, $15A wz, wc, wr, nr
        djnz $0A5, $15A nr, wr
        djnz $0A5, $15A wc, nr, wz
        djnz $0A5, $15A wr, wz, nr
        djnz $15A, #$0A5
        djnz $15A, #$0A5 wz
        djnz $15A, #$0A5 wc
        djnz $15A, #$0A5 wr
        djnz $15A, #$0A5 nr
        djnz $15A, #$0A5 wz, wc
        djnz $15A, #$0A5 wz, wr
        djnz $15A, #$0A5 wz, nr
        djnz $15A, #$0A5 wc, wr
        djnz $15A, #$0A5 wc, nr
        djnz $15A, #$0A5 wr, nr
        djnz $15A, #$0A5 wz, wc, wr
        djnz $15A, #$0A5 wz, wc, nr
        djnz $15A, #$0A5 wz, wr, nr
        djnz $15A, #$0A5 wc, wr, nr
        djnz $15A, #$0A5 wz, wc, wr, nr
        djnz $15A, #$0A5 nr, wr
        djnz $15A, #$0A5 wc, nr, wz
        djnz $15A, #$0A5 wr, wz, nr
        tjnz $0A5, $15A
        tjnz $0A5, $15A wz
        tjnz $0A5, $15A wc
        tjnz $0A5, $15A wr
        tjnz $0A5, $15A nr
        tjnz $0A5, $15A wz, wc
        tjnz $0A5, $15A wz, wr
        tjnz $0A5, $15A wz, nr
        tjnz $0A5, $15A wc, wr
        tjnz $0A5, $15A wc, nr
        tjnz $0A5, $15A wr, nr
        tjnz $0A5, $15A wz, wc, wr
        tjnz $0A5, $15A wz, wc, nr
        tjnz $0A5, $15A wz, wr, nr
        tjnz $0A5, $15A wc, wr, nr
        tjnz $0A5, $15A wz, wc, wr, nr
        tjnz $0A5, $15A nr, wr
        tjnz $0A5, $15A wc, nr, wz
        tjnz $0A5, $15A wr, wz, nr
        tjnz $15A, #$0A5
        tjnz $15A, #$0A5 wz
        tjnz $15A, #$0A5 wc
        tjnz $15A, #$0A5 wr
        tjnz $15A, #$0A5 nr
        tjnz $15A, #$0A5 wz, wc
        tjnz $15A, #$0A5 wz, wr
        tjnz $15A, #$0A5 wz, nr
        tjnz $15A, #$0A5 wc, wr
        tjnz $15A, #$0A5 wc, nr
        tjnz $15A, #$0A5 wr, nr
        tjnz $15A, #$0A5 wz, wc, wr
        tjnz $15A, #$0A5 wz, wc, nr
        tjnz $15A, #$0A5 wz, wr, nr
        tjnz $15A, #$0A5 wc, wr, nr
        tjnz $15A, #$0A5 wz, wc, wr, nr
        tjnz $15A, #$0A5 nr, wr
        tjnz $15A, #$0A5 wc, nr, wz
        tjnz $15A, #$0A5 wr, wz, nr
        tjz $0A5, $15A
        tjz $0A5, $15A wz
        tjz $0A5, $15A wc
        tjz $0A5, $15A wr
        tjz $0A5, $15A nr
        tjz $0A5, $15A wz, wc
        tjz $0A5, $15A wz, wr
        tjz $0A5, $15A wz, nr
        tjz $0A5, $15A wc, wr
        tjz $0A5, $15A wc, nr
        tjz $0A5, $15A wr, nr
        tjz $0A5, $15A wz, wc, wr
        tjz $0A5, $15A wz, wc, nr
        tjz $0A5, $15A wz, wr, nr
        tjz $0A5, $15A wc, wr, nr
        tjz $0A5, $15A wz, wc, wr, nr
        tjz $0A5, $15A nr, wr
        tjz $0A5, $15A wc, nr, wz
        tjz $0A5, $15A wr, wz, nr
        tjz $15A, #$0A5
        tjz $15A, #$0A5 wz
        tjz $15A, #$0A5 wc
        tjz $15A, #$0A5 wr
        tjz $15A, #$0A5 nr
        tjz $15A, #$0A5 wz, wc
        tjz $15A, #$0A5 wz, wr
        tjz $15A, #$0A5 wz, nr
        tjz $15A, #$0A5 wc, wr
        tjz $15A, #$0A5 wc, nr
        tjz $15A, #$0A5 wr, nr
        tjz $15A, #$0A5 wz, wc, wr
        tjz $15A, #$0A5 wz, wc, nr
        tjz $15A, #$0A5 wz, wr, nr
        tjz $15A, #$0A5 wc, wr, nr
        tjz $15A, #$0A5 wz, wc, wr, nr
        tjz $15A, #$0A5 nr, wr
        tjz $15A, #$0A5 wc, nr, wz
        tjz $15A, #$0A5 wr, wz, nr
        waitpeq $0A5, $15A
        waitpeq $0A5, $15A wz
        waitpeq $0A5, $15A wc
        waitpeq $0A5, $15A wr
        waitpeq $0A5, $15A nr
        waitpeq $0A5, $15A wz, wc
        waitpeq $0A5, $15A wz, wr
        waitpeq $0A5, $15A wz, nr
        waitpeq $0A5, $15A wc, wr
        waitpeq $0A5, $15A wc, nr
        waitpeq $0A5, $15A wr, nr
        waitpeq $0A5, $15A wz, wc, wr
        waitpeq $0A5, $15A wz, wc, nr
        waitpeq $0A5, $15A wz, wr, nr
        waitpeq $0A5, $15A wc, wr, nr
        waitpeq $0A5, $15A wz, wc, wr, nr
        waitpeq $0A5, $15A nr, wr
        waitpeq $0A5, $15A wc, nr, wz
        waitpeq $0A5, $15A wr, wz, nr
        waitpeq $15A, #$0A5
        waitpeq $15A, #$0A5 wz
        waitpeq $15A, #$0A5 wc
        waitpeq $15A, #$0A5 wr
        waitpeq $15A, #$0A5 nr
        waitpeq $15A, #$0A5 wz, wc
        waitpeq $15A, #$0A5 wz, wr
        waitpeq $15A, #$0A5 wz, nr
        waitpeq $15A, #$0A5 wc, wr
        waitpeq $15A, #$0A5 wc, nr
        waitpeq $15A, #$0A5 wr, nr
        waitpeq $15A, #$0A5 wz, wc, wr
        waitpeq $15A, #$0A5 wz, wc, nr
        waitpeq $15A, #$0A5 wz, wr, nr
        waitpeq $15A, #$0A5 wc, wr, nr
        waitpeq $15A, #$0A5 wz, wc, wr, nr
        waitpeq $15A, #$0A5 nr, wr
        waitpeq $15A, #$0A5 wc, nr, wz
        waitpeq $15A, #$0A5 wr, wz, nr
        waitpne $0A5, $15A
        waitpne $0A5, $15A wz
        waitpne $0A5, $15A wc
        waitpne $0A5, $15A wr
        waitpne $0A5, $15A nr
        waitpne $0A5, $15A wz, wc
        waitpne $0A5, $15A wz, wr
        waitpne $0A5, $15A wz, nr
        waitpne $0A5, $15A wc, wr
        waitpne $0A5, $15A wc, nr
        waitpne $0A5, $15A wr, nr
        waitpne $0A5, $15A wz, wc, wr
        waitpne $0A5, $15A wz, wc, nr
        waitpne $0A5, $15A wz, wr, nr
        waitpne $0A5, $15A wc, wr, nr
        waitpne $0A5, $15A wz, wc, wr, nr
        waitpne $0A5, $15A nr, wr
        waitpne $0A5, $15A wc, nr, wz
        waitpne $0A5, $15A wr, wz, nr
        waitpne $15A, #$0A5
        waitpne $15A, #$0A5 wz
        waitpne $15A, #$0A5 wc
        waitpne $15A, #$0A5 wr
        waitpne $15A, #$0A5 nr
        waitpne $15A, #$0A5 wz, wc
        waitpne $15A, #$0A5 wz, wr
        waitpne $15A, #$0A5 wz, nr
        waitpne $15A, #$0A5 wc, wr
        waitpne $15A, #$0A5 wc, nr
        waitpne $15A, #$0A5 wr, nr
        waitpne $15A, #$0A5 wz, wc, wr
        waitpne $15A, #$0A5 wz, wc, nr
        waitpne $15A, #$0A5 wz, wr, nr
        waitpne $15A, #$0A5 wc, wr, nr
        waitpne $15A, #$0A5 wz, wc, wr, nr
        waitpne $15A, #$0A5 nr, wr
        waitpne $15A, #$0A5 wc, nr, wz
        waitpne $15A, #$0A5 wr, wz, nr
        waitcnt $0A5, $15A
        waitcnt $0A5, $15A wz
        waitcnt $0A5, $15A wc
        waitcnt $0A5, $15A wr
        waitcnt $0A5, $15A nr
        waitcnt $0A5, $15A wz, wc
        waitcnt $0A5, $15A wz, wr
        waitcnt $0A5, $15A wz, nr
        waitcnt $0A5, $15A wc, wr
        waitcnt $0A5, $15A wc, nr
        waitcnt $0A5, $15A wr, nr
        waitcnt $0A5, $15A wz, wc, wr
        waitcnt $0A5, $15A wz, wc, nr
        waitcnt $0A5, $15A wz, wr, nr
        waitcnt $0A5, $15A wc, wr, nr
        waitcnt $0A5, $15A wz, wc, wr, nr
        waitcnt $0A5, $15A nr, wr
        waitcnt $0A5, $15A wc, nr, wz
        waitcnt $0A5, $15A wr, wz, nr
        waitcnt $15A, #$0A5
        waitcnt $15A, #$0A5 wz
        waitcnt $15A, #$0A5 wc
        waitcnt $15A, #$0A5 wr
        waitcnt $15A, #$0A5 nr
        waitcnt $15A, #$0A5 wz, wc
        waitcnt $15A, #$0A5 wz, wr
        waitcnt $15A, #$0A5 wz, nr
        waitcnt $15A, #$0A5 wc, wr
        waitcnt $15A, #$0A5 wc, nr
        waitcnt $15A, #$0A5 wr, nr
        waitcnt $15A, #$0A5 wz, wc, wr
        waitcnt $15A, #$0A5 wz, wc, nr
        waitcnt $15A, #$0A5 wz, wr, nr
        waitcnt $15A, #$0A5 wc, wr, nr
        waitcnt $15A, #$0A5 wz, wc, wr, nr
        waitcnt $15A, #$0A5 nr, wr
        waitcnt $15A, #$0A5 wc, nr, wz
        waitcnt $15A, #$0A5 wr, wz, nr
        waitvid $0A5, $15A
        waitvid $0A5, $15A wz
        waitvid $0A5, $15A wc
        waitvid $0A5, $15A wr
        org 0
        waitvid $0A5, $15A nr
        waitvid $0A5, $15A wz, wc
        waitvid $0A5, $15A wz, wr
        waitvid $0A5, $15A wz, nr
        waitvid $0A5, $15A wc, wr
        waitvid $0A5, $15A wc, nr
        waitvid $0A5, $15A wr, nr
        waitvid $0A5, $15A wz, wc, wr
        waitvid $0A5, $15A wz, wc, nr
        waitvid $0A5, $15A wz, wr, nr
        waitvid $0A5, $15A wc, wr, nr
        waitvid $0A5, $15A wz, wc, wr, nr
        waitvid $0A5, $15A nr, wr
        waitvid $0A5, $15A wc, nr, wz
        waitvid $0A5, $15A wr, wz, nr
        waitvid $15A, #$0A5
        waitvid $15A, #$0A5 wz
        waitvid $15A, #$0A5 wc
        waitvid $15A, #$0A5 wr
        waitvid $15A, #$0A5 nr
        waitvid $15A, #$0A5 wz, wc
        waitvid $15A, #$0A5 wz, wr
        waitvid $15A, #$0A5 wz, nr
        waitvid $15A, #$0A5 wc, wr
        waitvid $15A, #$0A5 wc, nr
        waitvid $15A, #$0A5 wr, nr
        waitvid $15A, #$0A5 wz, wc, wr
        waitvid $15A, #$0A5 wz, wc, nr
        waitvid $15A, #$0A5 wz, wr, nr
        waitvid $15A, #$0A5 wc, wr, nr
        waitvid $15A, #$0A5 wz, wc, wr, nr
        waitvid $15A, #$0A5 nr, wr
        waitvid $15A, #$0A5 wc, nr, wz
        waitvid $15A, #$0A5 wr, wz, nr
        nop
        MOV $005, #$003 WZ
        If_Nz Djnz $005, #$002 Wc

PUB main
