DAT
        org $123
lab     long 0
        org $1EE
lab_ret long 0
        org 0
        if_never mov $005, #$003
        if_never djnz $1FF, #$100 wz
        if_never jmp #$007
        if_never ret
        if_never call #lab
        if_never cogid $004 wc
        if_never test $001, $002 wc, wz
        if_nc_and_nz mov $005, #$003
        if_nc_and_nz djnz $1FF, #$100 wz
        if_nc_and_nz jmp #$007
        if_nc_and_nz ret
        if_nc_and_nz call #lab
        if_nc_and_nz cogid $004 wc
        if_nc_and_nz test $001, $002 wc, wz
        if_nz_and_nc mov $005, #$003
        if_nz_and_nc djnz $1FF, #$100 wz
        if_nz_and_nc jmp #$007
        if_nz_and_nc ret
        if_nz_and_nc call #lab
        if_nz_and_nc cogid $004 wc
        if_nz_and_nc test $001, $002 wc, wz
        if_a mov $005, #$003
        if_a djnz $1FF, #$100 wz
        if_a jmp #$007
        if_a ret
        if_a call #lab
        if_a cogid $004 wc
        if_a test $001, $002 wc, wz
        if_nc_and_z mov $005, #$003
        if_nc_and_z djnz $1FF, #$100 wz
        if_nc_and_z jmp #$007
        if_nc_and_z ret
        if_nc_and_z call #lab
        if_nc_and_z cogid $004 wc
        if_nc_and_z test $001, $002 wc, wz
        if_z_and_nc mov $005, #$003
        if_z_and_nc djnz $1FF, #$100 wz
        if_z_and_nc jmp #$007
        if_z_and_nc ret
        if_z_and_nc call #lab
        if_z_and_nc cogid $004 wc
        if_z_and_nc test $001, $002 wc, wz
        if_nc mov $005, #$003
        if_nc djnz $1FF, #$100 wz
        if_nc jmp #$007
        if_nc ret
        if_nc call #lab
        if_nc cogid $004 wc
        if_nc test $001, $002 wc, wz
        if_ae mov $005, #$003
        if_ae djnz $1FF, #$100 wz
        if_ae jmp #$007
        if_ae ret
        if_ae call #lab
        if_ae cogid $004 wc
        if_ae test $001, $002 wc, wz
        if_c_and_nz mov $005, #$003
        if_c_and_nz djnz $1FF, #$100 wz
        if_c_and_nz jmp #$007
        if_c_and_nz ret
        if_c_and_nz call #lab
        if_c_and_nz cogid $004 wc
        if_c_and_nz test $001, $002 wc, wz
        if_nz_and_c mov $005, #$003
        if_nz_and_c djnz $1FF, #$100 wz
        if_nz_and_c jmp #$007
        if_nz_and_c ret
        if_nz_and_c call #lab
        if_nz_and_c cogid $004 wc
        if_nz_and_c test $001, $002 wc, wz
        if_nz mov $005, #$003
        if_nz djnz $1FF, #$100 wz
        if_nz jmp #$007
        if_nz ret
        if_nz call #lab
        if_nz cogid $004 wc
        if_nz test $001, $002 wc, wz
        if_ne mov $005, #$003
        if_ne djnz $1FF, #$100 wz
        if_ne jmp #$007
        if_ne ret
        if_ne call #lab
        if_ne cogid $004 wc
        if_ne test $001, $002 wc, wz
        if_c_ne_z mov $005, #$003
        if_c_ne_z djnz $1FF, #$100 wz
        if_c_ne_z jmp #$007
        if_c_ne_z ret
        if_c_ne_z call #lab
        if_c_ne_z cogid $004 wc
        if_c_ne_z test $001, $002 wc, wz
        if_z_ne_c mov $005, #$003
        if_z_ne_c djnz $1FF, #$100 wz
        if_z_ne_c jmp #$007
        if_z_ne_c ret
        if_z_ne_c call #lab
        if_z_ne_c cogid $004 wc
        if_z_ne_c test $001, $002 wc, wz
        if_nc_or_nz mov $005, #$003
        if_nc_or_nz djnz $1FF, #$100 wz
        if_nc_or_nz jmp #$007
        if_nc_or_nz ret
        if_nc_or_nz call #lab
        if_nc_or_nz cogid $004 wc
        if_nc_or_nz test $001, $002 wc, wz
        if_nz_or_nc mov $005, #$003
        if_nz_or_nc djnz $1FF, #$100 wz
        if_nz_or_nc jmp #$007
        if_nz_or_nc ret
        if_nz_or_nc call #lab
        if_nz_or_nc cogid $004 wc
        if_nz_or_nc test $001, $002 wc, wz
        if_c_and_z mov $005, #$003
        if_c_and_z djnz $1FF, #$100 wz
        if_c_and_z jmp #$007
        if_c_and_z ret
        if_c_and_z call #lab
        if_c_and_z cogid $004 wc
        if_c_and_z test $001, $002 wc, wz
        if_z_and_c mov $005, #$003
        if_z_and_c djnz $1FF, #$100 wz
        if_z_and_c jmp #$007
        if_z_and_c ret
        if_z_and_c call #lab
        if_z_and_c cogid $004 wc
        if_z_and_c test $001, $002 wc, wz
        if_c_eq_z mov $005, #$003
        if_c_eq_z djnz $1FF, #$100 wz
        if_c_eq_z jmp #$007
        if_c_eq_z ret
        if_c_eq_z call #lab
        if_c_eq_z cogid $004 wc
        if_c_eq_z test $001, $002 wc, wz
        if_z_eq_c mov $005, #$003
        if_z_eq_c djnz $1FF, #$100 wz
        if_z_eq_c jmp #$007
        if_z_eq_c ret
        if_z_eq_c call #lab
        if_z_eq_c cogid $004 wc
        if_z_eq_c test $001, $002 wc, wz
        if_z mov $005, #$003
        if_z djnz $1FF, #$100 wz
        if_z jmp #$007
        if_z ret
        if_z call #lab
        if_z cogid $004 wc
        if_z test $001, $002 wc, wz
        if_e mov $005, #$003
        if_e djnz $1FF, #$100 wz
        if_e jmp #$007
        if_e ret
        if_e call #lab
        if_e cogid $004 wc
        if_e test $001, $002 wc, wz
        if_nc_or_z mov $005, #$003
        if_nc_or_z djnz $1FF, #$100 wz
        if_nc_or_z jmp #$007
        if_nc_or_z ret
        if_nc_or_z call #lab
        if_nc_or_z cogid $004 wc
        if_nc_or_z test $001, $002 wc, wz
        if_z_or_nc mov $005, #$003
        if_z_or_nc djnz $1FF, #$100 wz
        if_z_or_nc jmp #$007
        if_z_or_nc ret
        if_z_or_nc call #lab
        if_z_or_nc cogid $004 wc
        if_z_or_nc test $001, $002 wc, wz
        if_c mov $005, #$003
        if_c djnz $1FF, #$100 wz
        if_c jmp #$007
        if_c ret
        if_c call #lab
        if_c cogid $004 wc
        if_c test $001, $002 wc, wz
        if_b mov $005, #$003
        if_b djnz $1FF, #$100 wz
        if_b jmp #$007
        if_b ret
        if_b call #lab
        if_b cogid $004 wc
        if_b test $001, $002 wc, wz
        if_c_or_nz mov $005, #$003
        if_c_or_nz djnz $1FF, #$100 wz
        if_c_or_nz jmp #$007
        if_c_or_nz ret
        if_c_or_nz call #lab
        if_c_or_nz cogid $004 wc
        if_c_or_nz test $001, $002 wc, wz
        if_nz_or_c mov $005, #$003
        if_nz_or_c djnz $1FF, #$100 wz
        if_nz_or_c jmp #$007
        if_nz_or_c ret
        if_nz_or_c call #lab
        if_nz_or_c cogid $004 wc
        if_nz_or_c test $001, $002 wc, wz
        if_c_or_z mov $005, #$003
        if_c_or_z djnz $1FF, #$100 wz
        if_c_or_z jmp #$007
        if_c_or_z ret
        if_c_or_z call #lab
        if_c_or_z cogid $004 wc
        if_c_or_z test $001, $002 wc, wz
        if_z_or_c mov $005, #$003
        if_z_or_c djnz $1FF, #$100 wz
        if_z_or_c jmp #$007
        if_z_or_c ret
        if_z_or_c call #lab
        if_z_or_c cogid $004 wc
        if_z_or_c test $001, $002 wc, wz
        if_be mov $005, #$003
        if_be djnz $1FF, #$100 wz
        if_be jmp #$007
        if_be ret
        if_be call #lab
        if_be cogid $004 wc
        if_be test $001, $002 wc, wz
        if_always mov $005, #$003
        if_always djnz $1FF, #$100 wz
        if_always jmp #$007
        if_always ret
        if_always call #lab
        if_always cogid $004 wc
        if_always test $001, $002 wc, wz

PUB main
