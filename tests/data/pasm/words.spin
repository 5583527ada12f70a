DAT
        org $123
lab     long 0
        org $1EE
lab_ret long 0
        org 0
        nop
        if_nc_and_nz wrbyte $1C6, $141
        if_nc_or_nz wrbyte $093, #$020
        if_c_ne_z rdbyte $172, $12D
        if_nc_or_nz rdbyte $139, #$030
        if_c wrbyte $11E, $10A wc
        if_c_and_nz wrbyte $048, #$0AA wc
        if_c_eq_z rdbyte $0B1, $014 wc
        if_c_or_z rdbyte $16F, #$09E wc
        if_c_or_nz wrbyte $14C, $03E wz
        if_nc wrbyte $19E, #$0EF wz
        if_c_ne_z rdbyte $191, $031 wz
        if_nz rdbyte $02B, #$118 wz
        if_nc wrbyte $077, $190 wz, wc
        wrbyte $096, #$06D wz, wc
        if_c_ne_z rdbyte $1E7, $162 wz, wc
        if_c_and_z rdbyte $10E, #$063 wz, wc
        if_c_ne_z wrword $018, $103
        if_c_or_nz wrword $143, #$0C6
        if_nc_and_nz rdword $074, $16F
        if_nz rdword $161, #$02B
        wrword $134, $0D8 wc
        if_c_ne_z wrword $14B, #$159 wc
        if_c_or_z rdword $091, $1C4 wc
        if_c_and_nz rdword $151, #$053 wc
        if_c_or_nz wrword $06F, $0C5 wz
        if_c_or_nz wrword $157, #$188 wz
        if_c_eq_z rdword $037, $09C wz
        if_c_and_z rdword $057, #$06F wz
        if_nz wrword $0C4, $161 wz, wc
        if_never wrword $19E, #$065 wz, wc
        if_nc_and_z rdword $01A, $02C wz, wc
        if_z rdword $0A4, #$102 wz, wc
        if_c_or_z wrlong $035, $0CF
        if_nc_or_z wrlong $094, #$0C5
        if_c_eq_z rdlong $0C9, $180
        if_c_and_nz rdlong $001, #$12D
        if_nc_and_z wrlong $00C, $035 wc
        if_c_or_z wrlong $0D0, #$0EB wc
        rdlong $055, $173 wc
        if_c_and_z rdlong $07B, #$03A wc
        if_c_or_z wrlong $0D9, $1C0 wz
        if_c_and_nz wrlong $1E7, #$166 wz
        if_c_eq_z rdlong $0C8, $1A9 wz
        if_nc_or_z rdlong $007, #$07B wz
        if_c_and_z wrlong $1BC, $127 wz, wc
        if_nc_and_nz wrlong $06B, #$0AC wz, wc
        if_c_or_z rdlong $01A, $113 wz, wc
        if_c_or_z rdlong $010, #$16C wz, wc
        if_z hubop $0EA, $143
        if_z hubop $0D5, #$01A
        if_nz hubop $1D3, $1B2 wr
        if_c_and_nz hubop $050, #$11D wr
        if_never hubop $178, $126 wc
        if_c_ne_z hubop $13A, #$1AF wc
        hubop $1EA, $10A wc, wr
        if_c_eq_z hubop $094, #$0B7 wc, wr
        if_c_eq_z hubop $007, $10E wz
        if_c_or_nz hubop $196, #$097 wz
        if_nc hubop $0B3, $1A7 wz, wr
        if_nc_or_nz hubop $0C9, #$0B9 wz, wr
        if_never hubop $19C, $190 wz, wc
        if_c_eq_z hubop $0B3, #$0E8 wz, wc
        if_c_or_nz hubop $083, $1C4 wz, wc, wr
        if_nc_or_nz hubop $13F, #$176 wz, wc, wr
        long $1010D453
        long $105396B1
        long $108D1E8B
        long $10C59F75
        long $111102A6
        long $1148C98F
        long $118E62F7
        long $11E8C0D5
        long $123650AC
        long $12663C05
        long $1295E043
        long $12D9F21D
        long $133C419F
        long $13437CB4
        long $139A913C
        long $13E8DFC4
        long $143E2723
        long $14529F39
        long $14895806
        long $14E88BE8
        long $15121043
        long $1546CE4C
        long $15901862
        long $15D410DE
        long $161BA21E
        long $167161C6
        long $1681250E
        long $16C42635
        long $170D4B92
        long $174E8E2D
        long $17983278
        long $17E6C673
        long $181A8A86
        long $185E02E1
        long $18ABED51
        long $18E24D6C
        long $190C91D3
        long $197BE363
        long $199462F6
        long $19C5F379
        long $1A373F92
        long $1A5B4CF3
        long $1ABB4898
        long $1AF3F0BF
        long $1B0E9627
        long $1B62782E
        long $1BAAF9C0
        long $1BCFC09E
        long $1C32475B
        long $1C51BDB4
        long $1CAA387E
        long $1CF04309
        long $1D323B27
        long $1D679753
        long $1D98B128
        long $1DF5C0F5
        long $1E1AF4CF
        long $1E5F4C42
        long $1EB48EB4
        long $1EF22F61
        long $1F3548DA
        long $1F58BD59
        long $1F8B442A
        long $1FC9AE39
        if_nc_and_nz ror $018, $007 nr
        if_nz ror $087, #$07D nr
        if_nc_or_z ror $065, $1A7
        ror $1A7, #$049
        if_c_or_z ror $1EC, $016 wc, nr
        if_c_and_z ror $194, #$131 wc, nr
        if_c_or_nz ror $0D4, $067 wc
        if_c_ne_z ror $02C, #$09C wc
        if_c_ne_z ror $136, $148 wz, nr
        if_c_and_nz ror $01F, #$109 wz, nr
        ror $08E, $182 wz
        if_nc_or_z ror $173, #$14B wz
        if_nz ror $0FC, $040 wz, wc, nr
        if_c ror $05A, #$053 wz, wc, nr
        if_nc ror $0C4, $097 wz, wc
        if_nc_and_z ror $1EC, #$08C wz, wc
        if_c_ne_z rol $064, $105 nr
        if_c_and_z rol $0AC, #$13C nr
        if_c_and_nz rol $01D, $14D
        if_nc_and_z rol $1C7, #$15A
        if_z rol $1B3, $09B wc, nr
        if_nc rol $14B, #$1E7 wc, nr
        if_c_ne_z rol $059, $0D0 wc
        if_c_eq_z rol $0E2, #$0EE wc
        if_c_and_z rol $198, $0CD wz, nr
        if_nc_and_z rol $091, #$1F3 wz, nr
        if_c_or_nz rol $0A8, $192 wz
        if_c_eq_z rol $1D1, #$106 wz
        if_c rol $17D, $0ED wz, wc, nr
        if_nc_or_nz rol $0D2, #$1E6 wz, wc, nr
        if_c_eq_z rol VCFG, $0A7 wz, wc
        if_nz rol $057, #$15E wz, wc
        if_nc_or_nz shr $1AC, $1C5 nr
        if_nc_and_nz shr $0D1, #$0BF nr
        if_nz shr $193, $12C
        if_c_ne_z shr $0E1, #$108
        if_c_and_z shr $1DD, $04E wc, nr
        if_c shr $18C, #$112 wc, nr
        if_c_or_z shr $071, $0A5 wc
        if_c_or_z shr $1EB, #$1AB wc
        if_nc shr $055, $1A3 wz, nr
        if_never shr $1C3, #$042 wz, nr
        if_c_or_nz shr $158, $074 wz
        if_c_ne_z shr $0BF, #$1AC wz
        if_c_and_nz shr $0AE, $190 wz, wc, nr
        if_nz shr $0CA, #$13A wz, wc, nr
        if_nc_or_nz shr $021, $1BF wz, wc
        if_c_and_nz shr $1A1, #$148 wz, wc
        if_nc_or_nz shl $0E1, $197 nr
        if_z shl $053, #$00B nr
        if_nc_and_nz shl $189, $179
        shl $046, #$02D
        if_c_or_nz shl $00E, CTRA wc, nr
        if_never shl $06D, #$1F2 wc, nr
        if_nc_or_z shl $1A5, $04D wc
        if_never shl $10F, #$160 wc
        if_c_and_nz shl $0E6, $1DB wz, nr
        if_nc_or_nz shl $1AC, #$1B0 wz, nr
        if_nc_and_z shl $040, $176 wz
        if_never shl $174, #$1D7 wz
        if_nc_and_nz shl $0EF, $006 wz, wc, nr
        if_nc_and_nz shl $0B9, #$18B wz, wc, nr
        if_c_and_z shl $02C, $0DC wz, wc
        shl $158, #$066 wz, wc
        if_nc_or_nz rcr $08C, $116 nr
        if_c_or_nz rcr $009, #$020 nr
        if_c_and_z rcr $1D0, $0B0
        if_z rcr $0E6, #$18D
        rcr $13B, $05D wc, nr
        if_nc_and_nz rcr $09E, #$1A6 wc, nr
        if_nc rcr $0AA, $185 wc
        if_z rcr $034, #$163 wc
        if_z rcr $182, $094 wz, nr
        if_nc_or_nz rcr $0C0, #$19E wz, nr
        if_nz rcr $1A0, $132 wz
        rcr $1CB, #$175 wz
        if_c_and_z rcr $0FD, $148 wz, wc, nr
        if_z rcr $0FC, #$159 wz, wc, nr
        if_nz rcr $119, $0A8 wz, wc
        if_nz rcr $1A9, #$091 wz, wc
        if_c_and_z rcl $102, $13D nr
        if_nc_and_z rcl $04D, #$09B nr
        if_c_or_z rcl $0C0, $02C
        if_nc_and_z rcl $097, #$066
        if_z rcl $061, $09B wc, nr
        if_c_ne_z rcl $064, #$16B wc, nr
        rcl $09F, $0F4 wc
        if_never rcl $08E, #$1B7 wc
        if_c_eq_z rcl $069, $111 wz, nr
        if_nc_or_nz rcl $1CD, #$0DD wz, nr
        if_nc_and_nz rcl $1A4, $0F9 wz
        if_c_and_z rcl $18B, #$197 wz
        if_nc_or_nz rcl $111, $117 wz, wc, nr
        if_nc rcl $097, #$1A9 wz, wc, nr
        if_nz rcl $144, $1BF wz, wc
        if_c_and_z rcl $16F, #$07B wz, wc
        if_nc_or_z sar $1DB, $174 nr
        if_z sar $085, #$059 nr
        if_never sar $06C, $1E3
        if_nz sar $013, #$109
        if_nz sar $03F, $0D4 wc, nr
        if_c_or_z sar $07E, #$1ED wc, nr
        if_c_and_z sar $111, $10F wc
        if_c_or_nz sar $074, #$1C5 wc
        if_nc_or_z sar $1AE, $00C wz, nr
        if_c_and_z sar $0A3, #$158 wz, nr
        if_nc sar $03F, $15E wz
        if_nc_or_nz sar $10F, #$0C4 wz
        if_c_or_z sar $067, $089 wz, wc, nr
        if_c_or_nz sar $1B4, #$1F9 wz, wc, nr
        if_nc_and_nz sar $0A1, $1ED wz, wc
        if_nc_and_nz sar $1C0, #$0DB wz, wc
        if_nc rev $158, $110 nr
        if_nc_or_z rev $053, #$0F1 nr
        if_nc_and_z rev $0D1, $06B
        if_c_ne_z rev $0B9, #$184
        if_z rev $150, $02E wc, nr
        rev $1AE, #$00E wc, nr
        if_c_or_nz rev $0CC, $034 wc
        if_nc_or_z rev $044, #$158 wc
        if_c_and_nz rev $179, $050 wz, nr
        if_c_and_z rev $14D, #$1A0 wz, nr
        if_nz rev $081, $0DD wz
        if_c_eq_z rev $127, #$0EE wz
        if_nc_and_nz rev $138, $019 wz, wc, nr
        if_c_eq_z rev $06D, #$135 wz, wc, nr
        if_c_and_z rev $14C, $062 wz, wc
        org 0
        if_nz rev FRQB, #$14E wz, wc
        if_nc_or_z mins $148, $173 nr
        mins $0C5, #$19C nr
        if_c mins $059, $0C4
        if_c_or_z mins $0C8, #$130
        if_c_eq_z mins $12A, $05E wc, nr
        if_c mins FRQB, #$098 wc, nr
        if_nz mins $016, INA wc
        if_never mins $1C6, #$009 wc
        mins $100, $0BF wz, nr
        if_c_or_nz mins $00D, #$048 wz, nr
        if_nc_and_z mins $0B5, $0B0 wz
        if_nc_or_nz mins $02F, #$1AB wz
        if_nc_and_z mins $180, $062 wz, wc, nr
        if_nz mins $161, #$1D5 wz, wc, nr
        if_c mins $190, $05C wz, wc
        mins $0D7, #$03C wz, wc
        if_nc_and_nz maxs $129, $095 nr
        if_never maxs $124, #$11A nr
        if_nc_or_z maxs $063, $1D3
        if_c_and_z maxs PAR, #$106
        if_nc maxs $10F, $051 wc, nr
        if_nc_and_nz maxs $109, #$063 wc, nr
        if_nc_and_z maxs $138, $1CE wc
        if_c_or_nz maxs $1C0, #$197 wc
        if_z maxs $1AC, $05A wz, nr
        if_nc_and_nz maxs $1A3, #$165 wz, nr
        if_nc_and_z maxs $1ED, $15F wz
        if_c_ne_z maxs $078, #$1FF wz
        if_c_and_z maxs PAR, $023 wz, wc, nr
        if_c_and_nz maxs $126, #$151 wz, wc, nr
        if_c_eq_z maxs $0B5, $102 wz, wc
        maxs $0C6, #$048 wz, wc
        if_z min $039, $0E2 nr
        if_c_and_z min $0F0, #$11F nr
        if_c_or_z min $0C7, $045
        if_c_and_nz min $197, #$074
        if_c_or_z min $05F, $1D5 wc, nr
        if_nc min $116, #$1A8 wc, nr
        if_nz min $1D4, $0E4 wc
        min $025, #$1A4 wc
        if_nc_or_nz min $0A3, $1D7 wz, nr
        if_nc_and_z min $127, #$0BF wz, nr
        if_nz min $05E, $029 wz
        if_c_or_z min $0CE, #$1BD wz
        if_never min $0E9, $021 wz, wc, nr
        min $155, #$0B4 wz, wc, nr
        min $174, $018 wz, wc
        if_c min $087, #$0BA wz, wc
        if_nc_and_z max $158, $07F nr
        if_nc max $1E3, #$015 nr
        if_c_eq_z max $014, $1C2
        if_c_eq_z max $1DB, #$023
        if_c max $155, $0F1 wc, nr
        if_c_and_z max PHSA, #$1B5 wc, nr
        if_c_ne_z max $19B, DIRA wc
        if_nc_and_z max $1A0, #$125 wc
        if_c_or_z max $149, $1C1 wz, nr
        if_c_or_z max $082, #$1A6 wz, nr
        if_c_ne_z max $093, $0D4 wz
        if_nc max $0CD, #$186 wz
        if_c_and_nz max $073, $01A wz, wc, nr
        if_c_eq_z max $187, #$1AB wz, wc, nr
        if_z max $152, $133 wz, wc
        if_c_or_z max $1AC, #$07B wz, wc
        if_c_and_nz movs $1E5, $147 nr
        if_c_ne_z movs $085, #$0D7 nr
        if_c_eq_z movs $1C3, $189
        if_z movs $1C2, #$164
        if_nc_and_nz movs $06D, $0C5 wc, nr
        if_c_and_z movs CTRA, #$1EA wc, nr
        if_c_and_nz movs $119, $0E0 wc
        if_c movs $0ED, #$129 wc
        if_nz movs $181, $000 wz, nr
        if_c movs $0F3, #$1BC wz, nr
        if_nc_or_nz movs $03D, $09D wz
        if_nz movs $178, #$03F wz
        movs $162, $092 wz, wc, nr
        if_c_and_z movs $033, #$091 wz, wc, nr
        if_c_ne_z movs $142, $0FF wz, wc
        if_c_or_z movs $0F8, #$08A wz, wc
        if_c_and_nz movd $1CF, $071 nr
        if_c_eq_z movd $0E5, #$074 nr
        if_z movd $187, $12A
        if_c_eq_z movd $05A, #$164
        if_nc movd $0FB, $022 wc, nr
        if_nc_or_nz movd CNT, #$04D wc, nr
        if_nc_or_nz movd $04E, $049 wc
        if_z movd $097, #$1B6 wc
        if_c_and_nz movd $0E4, $103 wz, nr
        if_c_or_nz movd $0FF, #$141 wz, nr
        if_nc_or_nz movd $0BD, $0D8 wz
        if_z movd $094, #$022 wz
        if_c movd $0BD, $188 wz, wc, nr
        if_nz movd $025, #$13C wz, wc, nr
        if_c_eq_z movd $0E0, $01A wz, wc
        if_nz movd $03A, #$1F5 wz, wc
        if_c_or_z movi $18F, $122 nr
        if_c movi $0FA, #$0C9 nr
        if_c_eq_z movi $1A4, $037
        if_nc_and_nz movi $043, #$17A
        if_nc_and_z movi $0EC, $0C3 wc, nr
        if_c_and_nz movi $1DF, #$1C1 wc, nr
        if_z movi $05A, $18D wc
        if_nc movi $021, #$0ED wc
        if_nc_and_z movi $135, $0C8 wz, nr
        if_nc_or_z movi $0DA, #$0AC wz, nr
        if_c_or_z movi $098, $061 wz
        if_z movi $132, #$044 wz
        if_c_eq_z movi $0D5, $0E3 wz, wc, nr
        if_nc movi $139, #$18C wz, wc, nr
        if_c_and_z movi $150, $018 wz, wc
        if_c_or_z movi $0D2, #$0FE wz, wc
        if_nc_and_nz jmpret $0B3, $14E nr
        if_nz jmpret $0BA, #$1A5 nr
        if_z jmpret $10B, $1C0
        if_nc jmpret $04F, #$11C
        if_nc_or_z jmpret $029, VSCL wc, nr
        if_c_or_nz jmpret $1B9, #$040 wc, nr
        if_c_ne_z jmpret PAR, $0E3 wc
        if_nc jmpret $17D, #$062 wc
        if_nc_or_z jmpret $143, $02A wz, nr
        if_never jmpret $089, #$131 wz, nr
        if_c_or_nz jmpret $12F, $07C wz
        if_nc_or_nz jmpret $012, #$132 wz
        if_nc_or_z jmpret $13C, $0BE wz, wc, nr
        if_z jmpret $117, #$18A wz, wc, nr
        jmpret $00F, $074 wz, wc
        if_c_eq_z jmpret $13A, #$0F0 wz, wc
        if_c_or_z test $06F, $0BC
        if_c_ne_z test $0A4, #$0D1
        if_c_or_z and $115, $0D2
        if_nc and $116, #$012
        if_c test $071, $01F wc
        if_nc_or_nz test $122, #$070 wc
        if_c_and_z and $0BD, $0DE wc
        if_nc_or_z and $097, #$0BF wc
        if_nc_and_z test $1AA, $178 wz
        if_c_ne_z test $05B, #$1A4 wz
        if_never and $0AF, $07D wz
        if_nc_or_z and $1C9, #$076 wz
        if_never test $1AD, $13E wz, wc
        if_nc_or_z test $1D1, #$00C wz, wc
        if_nc_or_nz and $10E, $154 wz, wc
        if_c_and_nz and $04F, #$010 wz, wc
        testn $031, $0ED
        if_c_and_nz testn $1DB, #$01C
        if_z andn PAR, $17D
        if_c_or_nz andn $14A, #$030
        if_c_and_nz testn $1C2, $1AE wc
        if_nc testn $01C, #$1C2 wc
        if_c_or_z andn $14D, $193 wc
        if_c_eq_z andn $177, #$141 wc
        if_nc_or_z testn $1A7, $015 wz
        if_nc_or_z testn $0BD, #$151 wz
        andn $1BC, $0B0 wz
        if_c_and_nz andn $1CF, #$032 wz
        if_nc_and_nz testn $0C2, $172 wz, wc
        if_c testn $1B3, #$017 wz, wc
        if_c_or_z andn $171, $043 wz, wc
        if_nc_or_nz andn $1A7, #$173 wz, wc
        if_c_or_z or $06B, $1ED nr
        if_nz or $07F, #$1C5 nr
        if_c_and_z or $04E, $040
        if_c_or_z or $1E1, #$0CD
        if_c_or_nz or $023, $0FF wc, nr
        if_z or $013, #$151 wc, nr
        if_c_or_nz or $154, $0C1 wc
        if_c_eq_z or $0E9, #$0FB wc
        if_c_or_nz or $126, $067 wz, nr
        if_nc_and_z or $1C7, #$1D6 wz, nr
        if_never or $1B5, $0C8 wz
        if_c_or_nz or $1E4, #$0AA wz
        if_c_and_nz or $162, $018 wz, wc, nr
        or $16E, #$050 wz, wc, nr
        or $114, $0E0 wz, wc
        if_c or $151, #$198 wz, wc
        if_c xor $096, $122 nr
        if_nc_or_nz xor $058, #$183 nr
        if_nz xor $04E, $15B
        if_c_and_z xor $1CF, #$180
        if_c xor $0A6, $08B wc, nr
        xor $065, #$11D wc, nr
        if_nc_and_nz xor $133, $05A wc
        if_nc_and_z xor $102, #$099 wc
        if_never xor $0AE, $049 wz, nr
        if_nc_and_z xor $021, #$18C wz, nr
        if_nc xor $192, $189 wz
        if_c_eq_z xor $157, #$10D wz
        if_never xor $1E8, $1C1 wz, wc, nr
        if_nz xor $0D2, #$103 wz, wc, nr
        if_nc_or_nz xor $178, $0DF wz, wc
        if_c_and_z xor INB, #$13F wz, wc
        if_c_and_nz muxc $0B6, $0F4 nr
        if_nc_or_z muxc $132, #$1E9 nr
        if_never muxc $08D, $18D
        if_nc_and_nz muxc $1A5, #$1CF
        if_c muxc $0D7, $071 wc, nr
        if_c_eq_z muxc $09B, #$038 wc, nr
        if_nc_or_nz muxc $0A8, $02B wc
        if_c_and_z muxc $1C1, #$1F4 wc
        if_nc_and_z muxc $02D, $1EB wz, nr
        if_c muxc $166, #$0DE wz, nr
        if_nc_or_nz muxc $167, $112 wz
        if_c_or_nz muxc $08B, #$0D4 wz
        if_nc_or_z muxc $12E, $151 wz, wc, nr
        if_c_and_z muxc $13D, #$179 wz, wc, nr
        if_c_eq_z muxc $161, $094 wz, wc
        if_c muxc $1D8, #$038 wz, wc
        if_c_ne_z muxnc $101, $1D8 nr
        if_nc_or_nz muxnc $1CF, #$10F nr
        if_nc_and_nz muxnc $1A6, $10C
        if_nz muxnc $004, #$103
        if_c_and_z muxnc $1BB, $1A6 wc, nr
        if_c_or_z muxnc $0F9, #$03B wc, nr
        muxnc $09A, $1B8 wc
        if_never muxnc $140, #$0E7 wc
        if_c_eq_z muxnc $0BD, $052 wz, nr
        if_never muxnc $12D, #$1B6 wz, nr
        if_nc_or_nz muxnc $1AF, $0AA wz
        if_z muxnc $05F, #$0C7 wz
        if_z muxnc $098, $108 wz, wc, nr
        if_nc_or_z muxnc $00B, #$096 wz, wc, nr
        if_z muxnc $0AA, $15B wz, wc
        if_c_or_z muxnc $160, #$137 wz, wc
        if_nc_and_z muxz $16D, $003 nr
        if_z muxz $049, #$0B7 nr
        if_c_or_z muxz CTRA, $020
        if_c_and_z muxz $1E3, #$103
        muxz $1CD, $0B0 wc, nr
        muxz $1BE, #$050 wc, nr
        if_c_and_nz muxz $12F, $055 wc
        if_never muxz $09D, #$088 wc
        if_c_ne_z muxz $158, $1B1 wz, nr
        if_nc_or_z muxz $173, #$12B wz, nr
        if_nc muxz $129, $0FC wz
        if_nc_and_z muxz OUTA, #$1BC wz
        if_nc muxz $1B0, $1B5 wz, wc, nr
        if_c_ne_z muxz INA, #$16A wz, wc, nr
        if_c_and_z muxz $00A, $1B2 wz, wc
        if_c_ne_z muxz $033, #$05E wz, wc
        if_nz muxnz $07B, $0ED nr
        if_c_and_z muxnz $066, #$1AB nr
        muxnz $18E, $0B2
        if_nc muxnz $1C5, #$1ED
        if_c_or_nz muxnz $12A, $03F wc, nr
        if_c_and_z muxnz $136, #$127 wc, nr
        if_c_and_z muxnz $095, $090 wc
        if_c muxnz CNT, #$1EF wc
        if_c_eq_z muxnz $0FC, $07E wz, nr
        if_z muxnz $1D6, #$103 wz, nr
        if_nc_or_z muxnz $1B9, $03A wz
        if_nc_or_nz muxnz $044, #$02C wz
        if_nz muxnz $16C, $081 wz, wc, nr
        if_c_and_nz muxnz $1A7, #$029 wz, wc, nr
        if_nz muxnz $0DC, $156 wz, wc
        org 0
        if_nc_or_nz muxnz $176, #$0D4 wz, wc
        if_c add $177, $166 nr
        if_nc_or_nz add $0DD, #$0CE nr
        if_c_and_nz add $02A, $0D0
        if_c_or_z add $044, #$0CE
        if_c_and_nz add $10C, $07B wc, nr
        if_c_eq_z add $166, #$1B2 wc, nr
        if_c_and_nz add $0A7, $04C wc
        if_nc_or_z add $14E, #$0B9 wc
        if_c_or_z add $1D7, $1C7 wz, nr
        if_nc_and_z add INB, #$0B7 wz, nr
        if_never add $097, $136 wz
        if_c_ne_z add $18B, #$00E wz
        if_c_or_nz add $0CC, $0C8 wz, wc, nr
        if_c_eq_z add $02F, #$191 wz, wc, nr
        if_nc_or_z add $1A6, $110 wz, wc
        if_c add $185, #$1B8 wz, wc
        if_never cmp $155, $18C
        if_nz cmp $06F, #$1C7
        if_c_or_nz sub $185, $0C5
        if_c_ne_z sub $025, #$0EA
        if_c_or_nz cmp CNT, $1E0 wc
        if_c_and_z cmp $007, #$034 wc
        if_c_and_z sub $11A, $02E wc
        if_c_and_nz sub $192, #$078 wc
        if_c_ne_z cmp $19D, $07D wz
        if_c cmp $157, #$050 wz
        if_c_ne_z sub $050, $1CB wz
        if_c_eq_z sub $084, #$103 wz
        if_c_or_nz cmp $171, $029 wz, wc
        if_nc_or_nz cmp $116, #$181 wz, wc
        if_z sub $054, $0E5 wz, wc
        if_c sub $0DF, #$1C1 wz, wc
        if_nc_and_z addabs $17D, $1D2 nr
        if_c_and_nz addabs $0A9, #$0F5 nr
        if_z addabs $105, $010
        if_nc addabs $002, #$106
        if_c_or_nz addabs $052, $124 wc, nr
        if_z addabs $10F, #$0DB wc, nr
        if_c_and_nz addabs $1BD, $0C7 wc
        addabs $080, #$092 wc
        if_nc_or_z addabs $1C7, $1CC wz, nr
        if_c_and_z addabs $0FF, #$1E5 wz, nr
        if_nc_and_z addabs $0EA, $12A wz
        if_c_and_z addabs $0B6, #$196 wz
        if_nc_or_nz addabs $122, $012 wz, wc, nr
        if_nc_and_nz addabs $05F, #$0D2 wz, wc, nr
        if_nc addabs $0D1, $102 wz, wc
        if_z addabs $1D4, #$0EE wz, wc
        if_nc subabs $184, $088 nr
        if_c_and_z subabs $177, #$117 nr
        if_nz subabs $0A7, $0E3
        if_c_and_nz subabs $189, #$128
        if_nc_and_z subabs $1E6, PAR wc, nr
        subabs $06A, #$1B7 wc, nr
        if_c_or_z subabs $1A4, $003 wc
        if_c subabs $194, #$091 wc
        if_nc_or_nz subabs $067, INB wz, nr
        if_c_or_z subabs $0ED, #$1CF wz, nr
        if_c subabs $06B, $0DB wz
        if_z subabs VSCL, #$1A7 wz
        subabs $106, $1CF wz, wc, nr
        if_nz subabs $1D4, #$196 wz, wc, nr
        if_c_ne_z subabs $094, $193 wz, wc
        if_nc subabs $16F, #$1F0 wz, wc
        if_c_eq_z sumc $123, $066 nr
        if_nz sumc $1E3, #$123 nr
        if_nc_and_nz sumc $180, $0A5
        if_c_and_z sumc $0FA, #$07E
        sumc $0DD, $12A wc, nr
        sumc $0DC, #$072 wc, nr
        if_z sumc $192, $192 wc
        if_never sumc $06F, #$0FB wc
        if_c_or_z sumc $124, $001 wz, nr
        if_never sumc $055, #$1B3 wz, nr
        if_c_or_z sumc $128, $05F wz
        if_nc_or_z sumc $1DE, #$096 wz
        if_c_or_z sumc $1B8, $138 wz, wc, nr
        if_c_and_z sumc CTRB, #$174 wz, wc, nr
        sumc $012, $147 wz, wc
        if_c_ne_z sumc $0F5, #$1F4 wz, wc
        if_nc_and_nz sumnc $1D1, $087 nr
        if_nc_and_nz sumnc $1A1, #$122 nr
        if_c_and_nz sumnc $0CF, $142
        if_nc_or_nz sumnc $1DC, #$041
        if_nz sumnc $029, INB wc, nr
        if_c_eq_z sumnc $1B5, #$015 wc, nr
        if_c_eq_z sumnc $1DB, $029 wc
        sumnc $0E9, #$0E2 wc
        if_never sumnc $153, $106 wz, nr
        if_never sumnc $1A6, #$036 wz, nr
        if_c_or_z sumnc $1E3, $105 wz
        if_c_ne_z sumnc $0B3, #$049 wz
        if_c_and_nz sumnc $01B, $1DA wz, wc, nr
        if_nc_and_nz sumnc $0E0, #$086 wz, wc, nr
        sumnc $05F, $139 wz, wc
        if_c_or_nz sumnc $0CF, #$163 wz, wc
        if_nc sumz $0E8, $197 nr
        if_c_or_nz sumz $181, #$0D3 nr
        if_c sumz $1E4, $019
        if_nz sumz $077, #$16C
        sumz $01A, $118 wc, nr
        if_c_and_nz sumz $02D, #$0E1 wc, nr
        if_c sumz $0DF, $08C wc
        if_c_eq_z sumz $0B1, #$0B9 wc
        if_nc_and_z sumz $1B4, $123 wz, nr
        if_c_or_z sumz $12C, #$1F1 wz, nr
        if_c_or_nz sumz $169, $0A6 wz
        if_c_or_nz sumz $11D, #$0BE wz
        if_c_ne_z sumz $02D, $0F7 wz, wc, nr
        if_c_or_z sumz $03A, #$0A9 wz, wc, nr
        if_c_and_nz sumz $146, $075 wz, wc
        if_nz sumz $177, #$177 wz, wc
        if_nz sumnz $12E, $135 nr
        if_c_eq_z sumnz $020, #$1AF nr
        if_nc_and_nz sumnz $160, $075
        if_nc_or_z sumnz $01B, #$1FB
        if_c_and_z sumnz $072, $13E wc, nr
        if_c_and_nz sumnz $153, #$1C4 wc, nr
        if_c sumnz $085, $165 wc
        if_nc_and_z sumnz $196, #$09C wc
        if_c_and_z sumnz $094, $00C wz, nr
        if_c sumnz $1E1, #$143 wz, nr
        if_c_ne_z sumnz $113, $062 wz
        if_c sumnz $174, #$1AF wz
        if_nc_and_nz sumnz $169, $009 wz, wc, nr
        if_c_ne_z sumnz $1CB, #$018 wz, wc, nr
        if_nc sumnz $191, $17D wz, wc
        if_c_ne_z sumnz $021, #$1BF wz, wc
        if_c_eq_z mov $0AC, $0AA nr
        if_c_or_nz mov $061, #$029 nr
        if_nc_and_z mov $0E0, $114
        if_nc mov $0CC, #$155
        if_c_or_nz mov $13C, $1B3 wc, nr
        if_c_and_nz mov $139, #$030 wc, nr
        if_nc mov $1A8, $032 wc
        if_nc mov DIRB, #$171 wc
        if_nc mov $198, $121 wz, nr
        if_nc_or_nz mov $1AC, #$17F wz, nr
        if_never mov PHSB, $1A5 wz
        if_c_eq_z mov $13D, #$02D wz
        if_c_or_z mov $0EB, $1E4 wz, wc, nr
        if_z mov $1E9, #$1AA wz, wc, nr
        if_nc_or_nz mov $1A7, $1DB wz, wc
        if_c_and_z mov $110, #$08F wz, wc
        if_c neg $0D7, $1EB nr
        if_nc_and_z neg $04B, #$024 nr
        if_c_and_z neg $095, $058
        if_nc_and_nz neg $042, #$11C
        if_c_or_nz neg $01C, $151 wc, nr
        if_nc_and_z neg $006, #$0A0 wc, nr
        if_nc_or_nz neg $079, $103 wc
        if_c_and_z neg FRQB, #$1F8 wc
        if_nc_and_z neg $0DC, $039 wz, nr
        if_c_or_z neg $114, #$170 wz, nr
        if_nc_and_z neg $027, $0A0 wz
        if_nc_and_nz neg $140, #$1B6 wz
        if_nz neg $03F, $12E wz, wc, nr
        if_c_or_nz neg $1C7, #$1AD wz, wc, nr
        if_nz neg $008, $0C5 wz, wc
        if_c_or_nz neg $132, #$027 wz, wc
        if_z abs $003, $0BE nr
        if_nc_or_nz abs $155, #$071 nr
        abs $1B9, $1B2
        if_c_and_nz abs $0CB, #$0A7
        if_c_eq_z abs $04D, $19D wc, nr
        if_nc_or_z abs $0FE, #$14A wc, nr
        if_nz abs $16B, DIRA wc
        if_c_ne_z abs $162, #$1C8 wc
        if_nc abs $198, $059 wz, nr
        if_c_eq_z abs $154, #$04C wz, nr
        if_nz abs $01B, $072 wz
        if_never abs $1B3, #$07C wz
        abs $112, $010 wz, wc, nr
        abs $037, #$1AB wz, wc, nr
        if_nc_or_nz abs $075, $069 wz, wc
        if_nc abs $184, #$108 wz, wc
        if_c_or_nz absneg $1A9, $07C nr
        if_nc absneg $015, #$0C7 nr
        if_c_and_nz absneg $14F, $02F
        if_c_or_z absneg $17F, #$118
        if_never absneg $158, $033 wc, nr
        if_c_and_nz absneg $08C, #$130 wc, nr
        if_nc_and_nz absneg $12C, $1A2 wc
        if_c_and_z absneg $028, #$146 wc
        if_nz absneg $01D, $06E wz, nr
        if_c absneg $070, #$0FD wz, nr
        if_nc_or_nz absneg $1E2, $0C2 wz
        if_nc absneg $16A, #$03A wz
        if_c_ne_z absneg $1BB, $11A wz, wc, nr
        if_c_or_nz absneg $0BC, #$015 wz, wc, nr
        if_c_eq_z absneg OUTA, $1B3 wz, wc
        if_nc absneg $0F5, #$1C6 wz, wc
        if_nc_and_z negc $170, INB nr
        if_nc_and_z negc $1B7, #$01E nr
        if_z negc $1E5, $0E0
        if_c_or_z negc $084, #$1BB
        if_c_and_nz negc $086, $066 wc, nr
        if_c_ne_z negc $063, #$065 wc, nr
        negc $1A4, $143 wc
        if_z negc $023, #$1EB wc
        if_c negc $005, $1D7 wz, nr
        if_c_eq_z negc $175, #$0B9 wz, nr
        if_c_and_z negc $1BE, $1DA wz
        if_c_ne_z negc $050, #$079 wz
        if_c_or_z negc $1C3, $15A wz, wc, nr
        if_nc_and_nz negc $0D3, #$1EB wz, wc, nr
        if_c_ne_z negc $099, $1E2 wz, wc
        if_c_or_z negc $0F6, #$004 wz, wc
        if_c_ne_z negnc $0BC, $168 nr
        if_nz negnc $1BD, #$1D8 nr
        if_c_and_z negnc $018, $11B
        if_z negnc $033, #$0FC
        if_c_or_z negnc $10A, $1B0 wc, nr
        if_c_ne_z negnc $097, #$0B3 wc, nr
        if_z negnc $051, $054 wc
        if_c_or_z negnc $07A, #$074 wc
        if_c_and_nz negnc $1D3, $000 wz, nr
        if_c negnc $143, #$0A9 wz, nr
        if_c_or_z negnc $17B, $075 wz
        negnc $103, #$198 wz
        if_c_eq_z negnc $16D, $181 wz, wc, nr
        if_nc_and_z negnc $19A, #$111 wz, wc, nr
        if_c_and_nz negnc $0F7, $19A wz, wc
        if_nz negnc $039, #$1F4 wz, wc
        if_nc_or_nz negz $14C, $052 nr
        if_nc_or_nz negz $0B2, #$075 nr
        if_z negz $06A, $14F
        negz $028, #$098
        if_nc_and_nz negz $127, $11B wc, nr
        if_nc_or_z negz $127, #$1C9 wc, nr
        if_c_or_nz negz $122, $1B6 wc
        if_never negz $1AB, #$144 wc
        if_nc negz $179, $09D wz, nr
        if_c negz $0CA, #$1A0 wz, nr
        if_never negz $0D9, $1AC wz
        if_nc_and_nz negz $101, #$0C6 wz
        if_nz negz $023, $037 wz, wc, nr
        if_nc negz $01F, #$19F wz, wc, nr
        if_nz negz $115, $124 wz, wc
        if_c_or_nz negz $190, #$1E0 wz, wc
        if_nz negnz $03A, $059 nr
        if_z negnz $049, #$0C1 nr
        if_nc_and_nz negnz $034, $14F
        if_nc_and_nz negnz $1EB, #$1DF
        if_nz negnz $092, $0B4 wc, nr
        if_nc negnz $155, #$1DD wc, nr
        if_c_ne_z negnz $144, $176 wc
        if_nz negnz $039, #$03C wc
        if_nc_and_nz negnz $06A, $1A5 wz, nr
        if_nc_and_nz negnz $0F7, #$017 wz, nr
        if_c_ne_z negnz $07A, $122 wz
        if_nz negnz $040, #$155 wz
        if_c negnz $165, $041 wz, wc, nr
        if_nc_and_nz negnz $0F1, #$039 wz, wc, nr
        if_c_or_z negnz $04E, $1D5 wz, wc
        org 0
        if_c_and_nz negnz $1E0, #$079 wz, wc
        if_nz cmps $0F0, $0AC
        if_c_eq_z cmps $039, #$10E
        if_never cmps $1EA, $1CA wr
        if_c_or_nz cmps $18F, #$16C wr
        if_nc_or_z cmps $182, CTRA wc
        if_nz cmps $047, #$11A wc
        if_z cmps $008, $0F3 wc, wr
        if_nc cmps $149, #$114 wc, wr
        if_nc_or_z cmps $075, $027 wz
        if_c_ne_z cmps $02E, #$026 wz
        if_nc_or_nz cmps $056, $17D wz, wr
        if_c_and_z cmps $053, #$059 wz, wr
        if_never cmps $09B, $1A1 wz, wc
        if_c_eq_z cmps $0DD, #$00D wz, wc
        cmps $15D, $0B0 wz, wc, wr
        cmps $065, #$06B wz, wc, wr
        if_nc_or_z cmpsx $127, $058
        if_nc_and_nz cmpsx $181, #$179
        if_nc_or_nz cmpsx $0AE, $0FF wr
        if_c_and_nz cmpsx $1E2, #$07F wr
        if_nc cmpsx $037, $052 wc
        if_nc_or_nz cmpsx $030, #$0D1 wc
        if_nc cmpsx $02E, $1B0 wc, wr
        if_c_and_nz cmpsx $095, #$135 wc, wr
        if_nc_and_nz cmpsx $121, $006 wz
        if_nc_and_z cmpsx $12C, #$168 wz
        cmpsx $187, $12B wz, wr
        if_c_or_z cmpsx $105, #$12E wz, wr
        if_c_or_z cmpsx $093, $16A wz, wc
        if_z cmpsx $1AC, #$046 wz, wc
        if_c_ne_z cmpsx $01A, DIRA wz, wc, wr
        cmpsx $0D9, #$0BD wz, wc, wr
        if_c_or_nz addx $098, $1D9 nr
        if_nz addx $0B0, #$034 nr
        if_c addx $0B7, $1CC
        if_nc_or_nz addx $14C, #$175
        if_c_and_z addx $07A, $0B9 wc, nr
        if_c addx $178, #$147 wc, nr
        if_c_or_nz addx $15B, $0C6 wc
        if_nc_and_z addx $05F, #$057 wc
        if_c_ne_z addx $054, $074 wz, nr
        if_c_or_z addx $01D, #$069 wz, nr
        if_c_and_z addx $0A9, $090 wz
        if_c_or_z addx $1EB, #$12E wz
        if_c addx $0B4, $0F8 wz, wc, nr
        if_nc_and_z addx $1D2, #$099 wz, wc, nr
        if_nc addx $0BD, $0F4 wz, wc
        if_nc_and_nz addx $1DF, #$0B0 wz, wc
        cmpx $18E, $087
        if_nc_and_z cmpx $0B8, #$0FB
        if_nz subx $188, $142
        if_c_and_z subx $0C7, #$076
        if_nz cmpx $08B, $1DD wc
        cmpx $173, #$0B1 wc
        if_nc_or_z subx $066, $0F9 wc
        if_c subx $0C8, #$090 wc
        if_c_ne_z cmpx $17F, $17D wz
        if_c_eq_z cmpx VCFG, #$1C5 wz
        if_c_or_nz subx $05B, $036 wz
        if_nc_and_z subx $1B7, #$155 wz
        if_nz cmpx $1B2, $11B wz, wc
        if_c_ne_z cmpx $155, #$100 wz, wc
        if_nc_and_nz subx $1DB, $04F wz, wc
        if_nc_or_nz subx $101, #$1BD wz, wc
        if_c_eq_z adds $19A, $0C9 nr
        if_nc_and_nz adds $05D, #$0AF nr
        if_never adds PHSB, $1B1
        if_nz adds VCFG, #$027
        if_nc_and_nz adds $0B2, $138 wc, nr
        if_nc adds $0D5, #$0AC wc, nr
        if_c_and_z adds $182, $17C wc
        adds $0F2, #$177 wc
        if_nc_and_nz adds $091, $01A wz, nr
        if_nc adds $1C7, #$041 wz, nr
        if_nz adds $15B, $011 wz
        if_nz adds $147, #$000 wz
        if_c_or_z adds $069, $141 wz, wc, nr
        if_never adds $103, #$004 wz, wc, nr
        if_nc_or_z adds $118, $0B8 wz, wc
        if_z adds $1D7, #$02B wz, wc
        if_c_and_nz subs $171, $114 nr
        if_z subs $120, #$11B nr
        if_nc_and_z subs $046, $05A
        if_nc_or_nz subs $180, #$152
        if_nc_or_nz subs $043, $0D1 wc, nr
        if_c_ne_z subs $0DA, #$086 wc, nr
        if_c_or_nz subs $1D0, $11F wc
        if_c_and_z subs $144, #$1FD wc
        if_c_eq_z subs $1BD, $08B wz, nr
        if_never subs DIRA, #$0C9 wz, nr
        if_c subs $1D5, $19F wz
        if_c subs $198, #$094 wz
        if_nc_or_z subs $1ED, $0F9 wz, wc, nr
        if_c subs $08B, #$120 wz, wc, nr
        if_nz subs $025, $004 wz, wc
        if_c_and_z subs $0BB, #$0E3 wz, wc
        if_c_or_z addsx $1D7, $0A4 nr
        if_never addsx $0BD, #$159 nr
        if_nc addsx $05D, $001
        if_c_and_nz addsx $0B4, #$11C
        addsx $195, $160 wc, nr
        if_z addsx $19F, #$0F7 wc, nr
        addsx $0DB, $194 wc
        if_z addsx $124, #$1D5 wc
        if_c_ne_z addsx $10C, CTRA wz, nr
        if_c_ne_z addsx $1DA, #$109 wz, nr
        if_nc_or_z addsx $073, $1C1 wz
        if_c_eq_z addsx $044, #$179 wz
        if_z addsx $09B, $0E0 wz, wc, nr
        if_c addsx $187, #$1B2 wz, wc, nr
        if_c_or_nz addsx $045, $11A wz, wc
        if_nc_or_nz addsx $0BE, #$0F0 wz, wc
        if_c_or_z subsx $126, $011 nr
        if_c_or_z subsx $0D9, #$1ED nr
        if_nz subsx $166, $120
        if_c_and_nz subsx $1C8, #$14A
        if_c_eq_z subsx $11F, $082 wc, nr
        if_never subsx $1D2, #$1D8 wc, nr
        subsx PHSA, $1EC wc
        if_c_ne_z subsx $16E, #$100 wc
        if_nc_or_nz subsx $10B, $0DC wz, nr
        if_c_and_nz subsx $00E, #$128 wz, nr
        if_nc_and_nz subsx $19E, $03D wz
        if_never subsx $035, #$118 wz
        subsx $10A, $124 wz, wc, nr
        if_z subsx $055, #$078 wz, wc, nr
        if_nc_and_z subsx $06A, $127 wz, wc
        if_nc_or_nz subsx $167, #$197 wz, wc
        if_c cmpsub $048, $002 nr
        if_c_or_nz cmpsub $1EB, #$165 nr
        if_nc_or_nz cmpsub $161, $034
        if_nc_and_nz cmpsub $0DB, #$1E0
        if_z cmpsub $188, $121 wc, nr
        cmpsub $0C2, #$1B4 wc, nr
        if_c_and_nz cmpsub $1B7, $0F6 wc
        if_z cmpsub $192, #$0A9 wc
        if_c_eq_z cmpsub $017, $145 wz, nr
        if_c_and_z cmpsub $155, #$118 wz, nr
        if_c_and_nz cmpsub $16F, $17A wz
        if_c_and_nz cmpsub $16B, #$0D7 wz
        if_nc cmpsub $161, $0EE wz, wc, nr
        if_nz cmpsub $19F, #$090 wz, wc, nr
        if_nc_or_z cmpsub $08E, $137 wz, wc
        if_c_or_z cmpsub $0A8, #$187 wz, wc
        if_nc_and_z djnz $0CE, $0E4 nr
        if_c_and_nz djnz $121, #$16D nr
        if_never djnz $0FD, $19E
        if_c_eq_z djnz $0B9, #$044
        if_c_and_z djnz $121, $1C6 wc, nr
        if_c_ne_z djnz $025, #$0B5 wc, nr
        if_nc_and_z djnz $023, $0B5 wc
        if_z djnz $09A, #$0D0 wc
        if_nz djnz $02D, $168 wz, nr
        if_nc djnz $1BC, #$057 wz, nr
        if_never djnz $0A1, $0AE wz
        if_c_ne_z djnz $01A, #$1CD wz
        if_c_ne_z djnz $0C6, $120 wz, wc, nr
        if_c_eq_z djnz $171, #$009 wz, wc, nr
        if_c_and_nz djnz $181, $106 wz, wc
        if_nc_and_nz djnz $1B3, #$03E wz, wc
        if_c_and_z tjnz $101, $0D2
        if_nc_or_z tjnz $1CC, #$0CF
        if_c_or_z tjnz $1C9, $0F2 wr
        if_nc tjnz CNT, #$173 wr
        if_never tjnz $15C, $19F wc
        if_c_and_z tjnz $1AD, #$1F8 wc
        if_nc_or_z tjnz $11B, $0E2 wc, wr
        if_nc_or_z tjnz $09F, #$009 wc, wr
        if_z tjnz $0E7, $100 wz
        if_nc_or_z tjnz $1BD, #$0F6 wz
        if_c_eq_z tjnz $133, $173 wz, wr
        if_nc_or_nz tjnz OUTB, #$059 wz, wr
        if_nc_or_z tjnz $081, $1B0 wz, wc
        if_nc_and_nz tjnz $1E0, #$0A2 wz, wc
        if_nz tjnz $14B, $00C wz, wc, wr
        if_nc_and_z tjnz $0B3, #$029 wz, wc, wr
        if_nc_and_nz tjz $01E, $039
        if_nc_and_nz tjz $065, #$033
        if_nc_or_z tjz $0D0, $179 wr
        if_nc_or_z tjz $058, #$049 wr
        if_nz tjz $18C, $103 wc
        if_c_and_nz tjz $1BA, #$1D2 wc
        if_never tjz $09B, $085 wc, wr
        if_c_or_nz tjz $192, #$05F wc, wr
        if_nc_or_nz tjz $08D, $1D2 wz
        if_nz tjz $121, #$13A wz
        if_c tjz $03C, $001 wz, wr
        if_z tjz $1CC, #$0EA wz, wr
        if_nc_and_nz tjz $041, $0A9 wz, wc
        if_nc_and_nz tjz $01D, #$1AF wz, wc
        if_nc_or_z tjz $12D, $1C6 wz, wc, wr
        if_nc tjz $046, #$0FF wz, wc, wr
        waitpeq $09B, $0CC
        if_c_ne_z waitpeq $101, #$1B5
        if_c_or_z waitpeq $087, $0B8 wr
        if_nc_or_z waitpeq $123, #$1A8 wr
        if_nc_or_z waitpeq $18D, $0C3 wc
        if_nc_and_nz waitpeq $11C, #$04C wc
        if_c_or_z waitpeq $039, $101 wc, wr
        if_c waitpeq INA, #$04C wc, wr
        if_never waitpeq $047, $1C3 wz
        if_nc_or_nz waitpeq $09F, #$1BE wz
        if_z waitpeq $0C9, $009 wz, wr
        if_nz waitpeq $1B0, #$111 wz, wr
        if_c_and_nz waitpeq $133, $123 wz, wc
        if_nc_or_z waitpeq $048, #$073 wz, wc
        if_c_or_z waitpeq $1B0, $095 wz, wc, wr
        if_z waitpeq $00E, #$0E3 wz, wc, wr
        if_nc_or_z waitpne $101, $141
        if_nz waitpne $19A, #$018
        if_nc waitpne $1E5, $023 wr
        if_nc_and_z waitpne $01A, #$167 wr
        if_never waitpne $08D, $189 wc
        waitpne $009, #$013 wc
        if_c_or_nz waitpne $0DD, $080 wc, wr
        if_c waitpne $187, #$0F9 wc, wr
        if_c waitpne $03D, $0B8 wz
        if_c_or_nz waitpne $1A8, #$0CF wz
        if_c_eq_z waitpne $04E, $0DB wz, wr
        if_c_eq_z waitpne $07F, #$010 wz, wr
        if_c_and_nz waitpne $0DF, $155 wz, wc
        if_c_and_z waitpne $089, #$09D wz, wc
        if_c_or_z waitpne $092, $166 wz, wc, wr
        if_c_and_z waitpne $0DE, #$02F wz, wc, wr
        if_c_eq_z waitcnt $0CB, $154 nr
        if_nz waitcnt $06A, #$106 nr
        waitcnt $1A4, $02C
        if_c_or_nz waitcnt $181, #$0FF
        if_nc_and_z waitcnt $18F, $02D wc, nr
        if_c_or_z waitcnt $14B, #$0B5 wc, nr
        if_nc_or_nz waitcnt $17E, $109 wc
        if_c_or_nz waitcnt $03F, #$054 wc
        if_c_ne_z waitcnt $1E3, $1DE wz, nr
        if_c_or_nz waitcnt $177, #$087 wz, nr
        if_nc_and_nz waitcnt $026, $1CC wz
        if_c_and_nz waitcnt $1E3, #$080 wz
        if_nc_and_z waitcnt $0CC, $10A wz, wc, nr
        if_nc_or_nz waitcnt $05B, #$092 wz, wc, nr
        if_c_and_z waitcnt $0EE, $085 wz, wc
        if_never waitcnt $1AB, #$1C5 wz, wc
        if_nc_and_nz waitvid $16A, $119
        if_c_and_z waitvid $0D4, #$032
        if_c waitvid $0D4, $19F wr
        if_nc waitvid $0EF, #$12D wr
        if_nc_or_z waitvid $1DD, $1C4 wc
        if_never waitvid $0CF, #$040 wc
        if_c waitvid $1E2, $080 wc, wr
        if_nc_and_z waitvid $171, #$0C6 wc, wr
        if_c_or_nz waitvid $021, $0CB wz
        if_nz waitvid $0D5, #$0D4 wz
        if_nc_and_z waitvid $0ED, $1BE wz, wr
        waitvid $1C4, #$0E8 wz, wr
        if_never waitvid $10B, OUTA wz, wc
        if_never waitvid $056, #$1A7 wz, wc
        if_c_or_nz waitvid $1BB, $1C4 wz, wc, wr
        org 0
        if_c_eq_z waitvid $095, #$1D1 wz, wc, wr
        if_c hubop $000, $000
        if_c jmp $000
        if_c_and_nz hubop $001, $000
        if_c_and_nz jmpret $001, $000 nr
        if_z hubop VSCL, $000
        if_z jmpret VSCL, $000 nr
        if_c hubop $000, $001
        if_c jmp $001
        if_nc_and_nz hubop $001, $001
        if_nc_and_nz jmpret $001, $001 nr
        if_nc_or_z hubop VSCL, $001
        if_nc_or_z jmpret VSCL, $001 nr
        if_nc_or_z hubop $000, $002
        if_nc_or_z jmp $002
        if_c_eq_z hubop $001, $002
        if_c_eq_z jmpret $001, $002 nr
        if_c_eq_z hubop VSCL, $002
        if_c_eq_z jmpret VSCL, $002 nr
        if_nc_or_z hubop $000, $003
        if_nc_or_z jmp $003
        if_c_or_z hubop $001, $003
        if_c_or_z jmpret $001, $003 nr
        if_c_ne_z hubop VSCL, $003
        if_c_ne_z jmpret VSCL, $003 nr
        if_c_eq_z hubop $000, $004
        if_c_eq_z jmp $004
        hubop $001, $004
        jmpret $001, $004 nr
        if_c_ne_z hubop VSCL, $004
        if_c_ne_z jmpret VSCL, $004 nr
        if_c_ne_z hubop $000, $005
        if_c_ne_z jmp $005
        if_nc_or_nz hubop $001, $005
        if_nc_or_nz jmpret $001, $005 nr
        if_nc_or_z hubop VSCL, $005
        if_nc_or_z jmpret VSCL, $005 nr
        if_nc_and_z hubop $000, $006
        if_nc_and_z jmp $006
        if_c_or_nz hubop $001, $006
        if_c_or_nz jmpret $001, $006 nr
        if_nc_and_nz hubop VSCL, $006
        if_nc_and_nz jmpret VSCL, $006 nr
        if_z hubop $000, $007
        if_z jmp $007
        if_c_eq_z hubop $001, $007
        if_c_eq_z jmpret $001, $007 nr
        if_c_eq_z hubop VSCL, $007
        if_c_eq_z jmpret VSCL, $007 nr
        if_c_or_z hubop $000, $008
        if_c_or_z jmp $008
        if_z hubop $001, $008
        if_z jmpret $001, $008 nr
        if_nc_and_z hubop VSCL, $008
        if_nc_and_z jmpret VSCL, $008 nr
        if_nc_and_nz hubop $000, VSCL
        if_nc_and_nz jmp VSCL
        if_c_eq_z hubop $001, VSCL
        if_c_eq_z jmpret $001, VSCL nr
        if_never hubop VSCL, VSCL
        if_never jmpret VSCL, VSCL nr
        if_c_and_z clkset $000
        if_c_and_z ret
        if_never clkset $001
        if_never jmpret $001, #$000 nr
        if_c_ne_z clkset VSCL
        if_c_ne_z jmpret VSCL, #$000 nr
        if_c_and_z cogid $000 nr
        if_c_and_z jmp #$001
        if_c_or_nz cogid $001 nr
        if_c_or_nz jmpret $001, #$001 nr
        if_c cogid VSCL nr
        if_c jmpret VSCL, #$001 nr
        if_c_ne_z coginit $000
        if_c_ne_z jmp #$002
        if_c_ne_z coginit $001
        if_c_ne_z jmpret $001, #$002 nr
        if_c_and_nz coginit VSCL
        if_c_and_nz jmpret VSCL, #$002 nr
        if_nc_and_nz cogstop $000
        if_nc_and_nz jmp #$003
        if_nz cogstop $001
        if_nz jmpret $001, #$003 nr
        if_c_ne_z cogstop VSCL
        if_c_ne_z jmpret VSCL, #$003 nr
        locknew $000 nr
        jmp #$004
        if_nc_and_z locknew $001 nr
        if_nc_and_z jmpret $001, #$004 nr
        if_c locknew VSCL nr
        if_c jmpret VSCL, #$004 nr
        if_nz lockret $000
        if_nz jmp #$005
        if_nc_or_z lockret $001
        if_nc_or_z jmpret $001, #$005 nr
        if_c_and_z lockret VSCL
        if_c_and_z jmpret VSCL, #$005 nr
        if_z lockset $000
        if_z jmp #$006
        if_c_or_nz lockset $001
        if_c_or_nz jmpret $001, #$006 nr
        if_c lockset VSCL
        if_c jmpret VSCL, #$006 nr
        if_nc_or_z lockclr $000
        if_nc_or_z jmp #$007
        if_nc lockclr $001
        if_nc jmpret $001, #$007 nr
        if_c_eq_z lockclr VSCL
        if_c_eq_z jmpret VSCL, #$007 nr
        hubop $000, #$008
        jmp #$008
        if_nz hubop $001, #$008
        if_nz jmpret $001, #$008 nr
        hubop VSCL, #$008
        jmpret VSCL, #$008 nr
        if_nc hubop $000, #$1FF
        if_nc jmp #$1FF
        if_c_or_z hubop $001, #$1FF
        if_c_or_z jmpret $001, #$1FF nr
        if_nc_and_z hubop VSCL, #$1FF
        if_nc_and_z jmpret VSCL, #$1FF nr
        if_nc_or_z hubop $000, $000 wr
        if_nc_or_z jmpret $000, $000
        if_c_and_nz hubop $001, $000 wr
        if_c_and_nz jmpret $001, $000
        if_never hubop VSCL, $000 wr
        if_never jmpret VSCL, $000
        if_nc_and_nz hubop $000, $001 wr
        if_nc_and_nz jmpret $000, $001
        if_c_ne_z hubop $001, $001 wr
        if_c_ne_z jmpret $001, $001
        if_nc_and_nz hubop VSCL, $001 wr
        if_nc_and_nz jmpret VSCL, $001
        if_z hubop $000, $002 wr
        if_z jmpret $000, $002
        if_c hubop $001, $002 wr
        if_c jmpret $001, $002
        if_nc_or_nz hubop VSCL, $002 wr
        if_nc_or_nz jmpret VSCL, $002
        if_nc hubop $000, $003 wr
        if_nc jmpret $000, $003
        if_nc_and_z hubop $001, $003 wr
        if_nc_and_z jmpret $001, $003
        if_c_ne_z hubop VSCL, $003 wr
        if_c_ne_z jmpret VSCL, $003
        if_nz hubop $000, $004 wr
        if_nz jmpret $000, $004
        if_z hubop $001, $004 wr
        if_z jmpret $001, $004
        if_c_eq_z hubop VSCL, $004 wr
        if_c_eq_z jmpret VSCL, $004
        if_c hubop $000, $005 wr
        if_c jmpret $000, $005
        if_c_or_z hubop $001, $005 wr
        if_c_or_z jmpret $001, $005
        if_nc_and_z hubop VSCL, $005 wr
        if_nc_and_z jmpret VSCL, $005
        if_nz hubop $000, $006 wr
        if_nz jmpret $000, $006
        if_z hubop $001, $006 wr
        if_z jmpret $001, $006
        if_nc_or_nz hubop VSCL, $006 wr
        if_nc_or_nz jmpret VSCL, $006
        if_never hubop $000, $007 wr
        if_never jmpret $000, $007
        if_c_or_nz hubop $001, $007 wr
        if_c_or_nz jmpret $001, $007
        if_c_or_z hubop VSCL, $007 wr
        if_c_or_z jmpret VSCL, $007
        if_nz hubop $000, $008 wr
        if_nz jmpret $000, $008
        if_c_or_nz hubop $001, $008 wr
        if_c_or_nz jmpret $001, $008
        if_nc_and_z hubop VSCL, $008 wr
        if_nc_and_z jmpret VSCL, $008
        if_c_or_z hubop $000, VSCL wr
        if_c_or_z jmpret $000, VSCL
        if_nz hubop $001, VSCL wr
        if_nz jmpret $001, VSCL
        if_c_and_nz hubop VSCL, VSCL wr
        if_c_and_nz jmpret VSCL, VSCL
        if_c_ne_z clkset $000 wr
        if_c_ne_z jmpret $000, #$000
        if_nz clkset $001 wr
        if_nz jmpret $001, #$000
        if_c_and_z clkset VSCL wr
        if_c_and_z jmpret VSCL, #$000
        if_c_or_nz cogid $000
        if_c_or_nz jmpret $000, #$001
        if_z cogid $001
        if_z jmpret $001, #$001
        cogid VSCL
        jmpret VSCL, #$001
        if_c_or_z coginit $000 wr
        if_c_or_z jmpret $000, #$002
        if_nc_and_z coginit $001 wr
        if_nc_and_z jmpret $001, #$002
        if_never coginit VSCL wr
        if_never jmpret VSCL, #$002
        if_c_and_z cogstop $000 wr
        if_c_and_z jmpret $000, #$003
        if_c cogstop $001 wr
        if_c jmpret $001, #$003
        cogstop VSCL wr
        jmpret VSCL, #$003
        if_never locknew $000
        if_never jmpret $000, #$004
        if_nc_or_nz locknew $001
        if_nc_or_nz jmpret $001, #$004
        locknew VSCL
        jmpret VSCL, #$004
        if_c_or_z lockret $000 wr
        if_c_or_z jmpret $000, #$005
        if_c_and_z lockret $001 wr
        if_c_and_z jmpret $001, #$005
        if_nz lockret VSCL wr
        if_nz jmpret VSCL, #$005
        if_c_and_z lockset $000 wr
        if_c_and_z jmpret $000, #$006
        if_nc_or_z lockset $001 wr
        if_nc_or_z jmpret $001, #$006
        if_nc lockset VSCL wr
        if_nc jmpret VSCL, #$006
        lockclr $000 wr
        jmpret $000, #$007
        if_nc_or_z lockclr $001 wr
        if_nc_or_z jmpret $001, #$007
        if_nz lockclr VSCL wr
        if_nz jmpret VSCL, #$007
        if_nz hubop $000, #$008 wr
        if_nz jmpret $000, #$008
        if_c_or_nz hubop $001, #$008 wr
        if_c_or_nz jmpret $001, #$008
        if_never hubop VSCL, #$008 wr
        if_never jmpret VSCL, #$008
        if_c_and_z hubop $000, #$1FF wr
        if_c_and_z jmpret $000, #$1FF
        if_c_and_z hubop $001, #$1FF wr
        if_c_and_z jmpret $001, #$1FF
        if_c_eq_z hubop VSCL, #$1FF wr
        if_c_eq_z jmpret VSCL, #$1FF
        if_c_or_nz hubop $000, $000 wc
        if_c_or_nz jmp $000 wc
        if_c_eq_z hubop $001, $000 wc
        if_c_eq_z jmpret $001, $000 wc, nr
        if_nc_or_nz hubop VSCL, $000 wc
        if_nc_or_nz jmpret VSCL, $000 wc, nr
        if_c hubop $000, $001 wc
        if_c jmp $001 wc
        if_z hubop $001, $001 wc
        if_z jmpret $001, $001 wc, nr
        if_nc_or_nz hubop VSCL, $001 wc
        if_nc_or_nz jmpret VSCL, $001 wc, nr
        if_nc_and_z hubop $000, $002 wc
        if_nc_and_z jmp $002 wc
        if_c_and_nz hubop $001, $002 wc
        org 0
        if_c_and_nz jmpret $001, $002 wc, nr
        if_c hubop VSCL, $002 wc
        if_c jmpret VSCL, $002 wc, nr
        if_c_or_z hubop $000, $003 wc
        if_c_or_z jmp $003 wc
        if_nc_and_z hubop $001, $003 wc
        if_nc_and_z jmpret $001, $003 wc, nr
        if_c_and_z hubop VSCL, $003 wc
        if_c_and_z jmpret VSCL, $003 wc, nr
        hubop $000, $004 wc
        jmp $004 wc
        if_nc_or_z hubop $001, $004 wc
        if_nc_or_z jmpret $001, $004 wc, nr
        if_c_ne_z hubop VSCL, $004 wc
        if_c_ne_z jmpret VSCL, $004 wc, nr
        if_nc_and_z hubop $000, $005 wc
        if_nc_and_z jmp $005 wc
        if_c_ne_z hubop $001, $005 wc
        if_c_ne_z jmpret $001, $005 wc, nr
        if_c_eq_z hubop VSCL, $005 wc
        if_c_eq_z jmpret VSCL, $005 wc, nr
        if_c_eq_z hubop $000, $006 wc
        if_c_eq_z jmp $006 wc
        if_nz hubop $001, $006 wc
        if_nz jmpret $001, $006 wc, nr
        if_z hubop VSCL, $006 wc
        if_z jmpret VSCL, $006 wc, nr
        if_nc_and_nz hubop $000, $007 wc
        if_nc_and_nz jmp $007 wc
        if_c_or_z hubop $001, $007 wc
        if_c_or_z jmpret $001, $007 wc, nr
        if_c_or_nz hubop VSCL, $007 wc
        if_c_or_nz jmpret VSCL, $007 wc, nr
        if_c_or_nz hubop $000, $008 wc
        if_c_or_nz jmp $008 wc
        if_c_eq_z hubop $001, $008 wc
        if_c_eq_z jmpret $001, $008 wc, nr
        if_nc_and_z hubop VSCL, $008 wc
        if_nc_and_z jmpret VSCL, $008 wc, nr
        hubop $000, VSCL wc
        jmp VSCL wc
        hubop $001, VSCL wc
        jmpret $001, VSCL wc, nr
        if_c_ne_z hubop VSCL, VSCL wc
        if_c_ne_z jmpret VSCL, VSCL wc, nr
        if_c_eq_z clkset $000 wc
        if_c_eq_z ret wc
        if_c clkset $001 wc
        if_c jmpret $001, #$000 wc, nr
        if_c_ne_z clkset VSCL wc
        if_c_ne_z jmpret VSCL, #$000 wc, nr
        if_nc_and_z cogid $000 wc, nr
        if_nc_and_z jmp #$001 wc
        if_c cogid $001 wc, nr
        if_c jmpret $001, #$001 wc, nr
        if_nz cogid VSCL wc, nr
        if_nz jmpret VSCL, #$001 wc, nr
        if_c_or_z coginit $000 wc
        if_c_or_z jmp #$002 wc
        if_nc_or_z coginit $001 wc
        if_nc_or_z jmpret $001, #$002 wc, nr
        if_nz coginit VSCL wc
        if_nz jmpret VSCL, #$002 wc, nr
        if_c_ne_z cogstop $000 wc
        if_c_ne_z jmp #$003 wc
        if_nc_and_nz cogstop $001 wc
        if_nc_and_nz jmpret $001, #$003 wc, nr
        if_c_or_z cogstop VSCL wc
        if_c_or_z jmpret VSCL, #$003 wc, nr
        if_c locknew $000 wc, nr
        if_c jmp #$004 wc
        if_c_ne_z locknew $001 wc, nr
        if_c_ne_z jmpret $001, #$004 wc, nr
        if_c_ne_z locknew VSCL wc, nr
        if_c_ne_z jmpret VSCL, #$004 wc, nr
        if_c_ne_z lockret $000 wc
        if_c_ne_z jmp #$005 wc
        if_c_and_nz lockret $001 wc
        if_c_and_nz jmpret $001, #$005 wc, nr
        if_nc_or_z lockret VSCL wc
        if_nc_or_z jmpret VSCL, #$005 wc, nr
        if_nc_or_nz lockset $000 wc
        if_nc_or_nz jmp #$006 wc
        if_c lockset $001 wc
        if_c jmpret $001, #$006 wc, nr
        if_c_ne_z lockset VSCL wc
        if_c_ne_z jmpret VSCL, #$006 wc, nr
        if_nc lockclr $000 wc
        if_nc jmp #$007 wc
        if_nc_or_z lockclr $001 wc
        if_nc_or_z jmpret $001, #$007 wc, nr
        if_c_ne_z lockclr VSCL wc
        if_c_ne_z jmpret VSCL, #$007 wc, nr
        if_nc_or_nz hubop $000, #$008 wc
        if_nc_or_nz jmp #$008 wc
        if_c_or_z hubop $001, #$008 wc
        if_c_or_z jmpret $001, #$008 wc, nr
        if_nc_or_z hubop VSCL, #$008 wc
        if_nc_or_z jmpret VSCL, #$008 wc, nr
        if_c_or_z hubop $000, #$1FF wc
        if_c_or_z jmp #$1FF wc
        if_c_eq_z hubop $001, #$1FF wc
        if_c_eq_z jmpret $001, #$1FF wc, nr
        if_nz hubop VSCL, #$1FF wc
        if_nz jmpret VSCL, #$1FF wc, nr
        if_c_or_nz hubop $000, $000 wc, wr
        if_c_or_nz jmpret $000, $000 wc
        if_c_and_z hubop $001, $000 wc, wr
        if_c_and_z jmpret $001, $000 wc
        if_c_eq_z hubop VSCL, $000 wc, wr
        if_c_eq_z jmpret VSCL, $000 wc
        if_nc_and_nz hubop $000, $001 wc, wr
        if_nc_and_nz jmpret $000, $001 wc
        if_c_ne_z hubop $001, $001 wc, wr
        if_c_ne_z jmpret $001, $001 wc
        if_nc_and_nz hubop VSCL, $001 wc, wr
        if_nc_and_nz jmpret VSCL, $001 wc
        if_c_and_z hubop $000, $002 wc, wr
        if_c_and_z jmpret $000, $002 wc
        if_nz hubop $001, $002 wc, wr
        if_nz jmpret $001, $002 wc
        if_nc_and_z hubop VSCL, $002 wc, wr
        if_nc_and_z jmpret VSCL, $002 wc
        if_nz hubop $000, $003 wc, wr
        if_nz jmpret $000, $003 wc
        if_c hubop $001, $003 wc, wr
        if_c jmpret $001, $003 wc
        if_z hubop VSCL, $003 wc, wr
        if_z jmpret VSCL, $003 wc
        if_z hubop $000, $004 wc, wr
        if_z jmpret $000, $004 wc
        if_nc_or_z hubop $001, $004 wc, wr
        if_nc_or_z jmpret $001, $004 wc
        if_c_eq_z hubop VSCL, $004 wc, wr
        if_c_eq_z jmpret VSCL, $004 wc
        if_c_or_z hubop $000, $005 wc, wr
        if_c_or_z jmpret $000, $005 wc
        if_nc_or_nz hubop $001, $005 wc, wr
        if_nc_or_nz jmpret $001, $005 wc
        if_c_eq_z hubop VSCL, $005 wc, wr
        if_c_eq_z jmpret VSCL, $005 wc
        if_never hubop $000, $006 wc, wr
        if_never jmpret $000, $006 wc
        if_nc_or_z hubop $001, $006 wc, wr
        if_nc_or_z jmpret $001, $006 wc
        if_z hubop VSCL, $006 wc, wr
        if_z jmpret VSCL, $006 wc
        if_nc_and_z hubop $000, $007 wc, wr
        if_nc_and_z jmpret $000, $007 wc
        if_c_eq_z hubop $001, $007 wc, wr
        if_c_eq_z jmpret $001, $007 wc
        if_c_and_z hubop VSCL, $007 wc, wr
        if_c_and_z jmpret VSCL, $007 wc
        if_nz hubop $000, $008 wc, wr
        if_nz jmpret $000, $008 wc
        hubop $001, $008 wc, wr
        jmpret $001, $008 wc
        if_nc_and_nz hubop VSCL, $008 wc, wr
        if_nc_and_nz jmpret VSCL, $008 wc
        if_z hubop $000, VSCL wc, wr
        if_z jmpret $000, VSCL wc
        if_c_or_nz hubop $001, VSCL wc, wr
        if_c_or_nz jmpret $001, VSCL wc
        if_never hubop VSCL, VSCL wc, wr
        if_never jmpret VSCL, VSCL wc
        if_c_eq_z clkset $000 wc, wr
        if_c_eq_z jmpret $000, #$000 wc
        if_c_or_nz clkset $001 wc, wr
        if_c_or_nz jmpret $001, #$000 wc
        if_nc_and_nz clkset VSCL wc, wr
        if_nc_and_nz jmpret VSCL, #$000 wc
        if_c_eq_z cogid $000 wc
        if_c_eq_z jmpret $000, #$001 wc
        if_c_and_z cogid $001 wc
        if_c_and_z jmpret $001, #$001 wc
        if_c_and_nz cogid VSCL wc
        if_c_and_nz jmpret VSCL, #$001 wc
        if_nc_or_z coginit $000 wc, wr
        if_nc_or_z jmpret $000, #$002 wc
        if_c_or_z coginit $001 wc, wr
        if_c_or_z jmpret $001, #$002 wc
        if_nc_and_nz coginit VSCL wc, wr
        if_nc_and_nz jmpret VSCL, #$002 wc
        if_never cogstop $000 wc, wr
        if_never jmpret $000, #$003 wc
        if_c_or_z cogstop $001 wc, wr
        if_c_or_z jmpret $001, #$003 wc
        if_c_or_z cogstop VSCL wc, wr
        if_c_or_z jmpret VSCL, #$003 wc
        if_nc_and_nz locknew $000 wc
        if_nc_and_nz jmpret $000, #$004 wc
        if_c_ne_z locknew $001 wc
        if_c_ne_z jmpret $001, #$004 wc
        if_nc_and_z locknew VSCL wc
        if_nc_and_z jmpret VSCL, #$004 wc
        lockret $000 wc, wr
        jmpret $000, #$005 wc
        if_c lockret $001 wc, wr
        if_c jmpret $001, #$005 wc
        lockret VSCL wc, wr
        jmpret VSCL, #$005 wc
        if_nc_or_z lockset $000 wc, wr
        if_nc_or_z jmpret $000, #$006 wc
        if_c_or_nz lockset $001 wc, wr
        if_c_or_nz jmpret $001, #$006 wc
        if_c_ne_z lockset VSCL wc, wr
        if_c_ne_z jmpret VSCL, #$006 wc
        if_nc_or_nz lockclr $000 wc, wr
        if_nc_or_nz jmpret $000, #$007 wc
        if_nz lockclr $001 wc, wr
        if_nz jmpret $001, #$007 wc
        if_c_or_nz lockclr VSCL wc, wr
        if_c_or_nz jmpret VSCL, #$007 wc
        if_nc_and_z hubop $000, #$008 wc, wr
        if_nc_and_z jmpret $000, #$008 wc
        if_nc hubop $001, #$008 wc, wr
        if_nc jmpret $001, #$008 wc
        if_nz hubop VSCL, #$008 wc, wr
        if_nz jmpret VSCL, #$008 wc
        if_nz hubop $000, #$1FF wc, wr
        if_nz jmpret $000, #$1FF wc
        if_nc_or_z hubop $001, #$1FF wc, wr
        if_nc_or_z jmpret $001, #$1FF wc
        if_c_and_nz hubop VSCL, #$1FF wc, wr
        if_c_and_nz jmpret VSCL, #$1FF wc
        if_nc_and_z hubop $000, $000 wz
        if_nc_and_z jmp $000 wz
        if_never hubop $001, $000 wz
        if_never jmpret $001, $000 wz, nr
        if_c_ne_z hubop VSCL, $000 wz
        if_c_ne_z jmpret VSCL, $000 wz, nr
        if_c_and_nz hubop $000, $001 wz
        if_c_and_nz jmp $001 wz
        if_c_eq_z hubop $001, $001 wz
        if_c_eq_z jmpret $001, $001 wz, nr
        if_c_eq_z hubop VSCL, $001 wz
        if_c_eq_z jmpret VSCL, $001 wz, nr
        if_nz hubop $000, $002 wz
        if_nz jmp $002 wz
        if_z hubop $001, $002 wz
        if_z jmpret $001, $002 wz, nr
        if_c_and_z hubop VSCL, $002 wz
        if_c_and_z jmpret VSCL, $002 wz, nr
        if_c_or_z hubop $000, $003 wz
        if_c_or_z jmp $003 wz
        if_c_and_z hubop $001, $003 wz
        if_c_and_z jmpret $001, $003 wz, nr
        if_nc_and_nz hubop VSCL, $003 wz
        if_nc_and_nz jmpret VSCL, $003 wz, nr
        hubop $000, $004 wz
        jmp $004 wz
        if_c_and_nz hubop $001, $004 wz
        if_c_and_nz jmpret $001, $004 wz, nr
        if_never hubop VSCL, $004 wz
        if_never jmpret VSCL, $004 wz, nr
        if_nz hubop $000, $005 wz
        org 0
        if_nz jmp $005 wz
        if_c_or_z hubop $001, $005 wz
        if_c_or_z jmpret $001, $005 wz, nr
        if_nc_and_z hubop VSCL, $005 wz
        if_nc_and_z jmpret VSCL, $005 wz, nr
        if_nc_and_z hubop $000, $006 wz
        if_nc_and_z jmp $006 wz
        if_c_or_z hubop $001, $006 wz
        if_c_or_z jmpret $001, $006 wz, nr
        hubop VSCL, $006 wz
        jmpret VSCL, $006 wz, nr
        if_nc_or_z hubop $000, $007 wz
        if_nc_or_z jmp $007 wz
        if_nc_or_z hubop $001, $007 wz
        if_nc_or_z jmpret $001, $007 wz, nr
        if_z hubop VSCL, $007 wz
        if_z jmpret VSCL, $007 wz, nr
        if_c hubop $000, $008 wz
        if_c jmp $008 wz
        if_nc_and_z hubop $001, $008 wz
        if_nc_and_z jmpret $001, $008 wz, nr
        if_c_or_z hubop VSCL, $008 wz
        if_c_or_z jmpret VSCL, $008 wz, nr
        if_c_or_z hubop $000, VSCL wz
        if_c_or_z jmp VSCL wz
        if_nc_and_z hubop $001, VSCL wz
        if_nc_and_z jmpret $001, VSCL wz, nr
        if_c_or_z hubop VSCL, VSCL wz
        if_c_or_z jmpret VSCL, VSCL wz, nr
        if_c_eq_z clkset $000 wz
        if_c_eq_z ret wz
        if_z clkset $001 wz
        if_z jmpret $001, #$000 wz, nr
        if_nz clkset VSCL wz
        if_nz jmpret VSCL, #$000 wz, nr
        if_nc cogid $000 wz, nr
        if_nc jmp #$001 wz
        if_z cogid $001 wz, nr
        if_z jmpret $001, #$001 wz, nr
        if_c_or_z cogid VSCL wz, nr
        if_c_or_z jmpret VSCL, #$001 wz, nr
        if_nc_and_z coginit $000 wz
        if_nc_and_z jmp #$002 wz
        if_c_or_z coginit $001 wz
        if_c_or_z jmpret $001, #$002 wz, nr
        if_z coginit VSCL wz
        if_z jmpret VSCL, #$002 wz, nr
        if_c_ne_z cogstop $000 wz
        if_c_ne_z jmp #$003 wz
        if_never cogstop $001 wz
        if_never jmpret $001, #$003 wz, nr
        if_nz cogstop VSCL wz
        if_nz jmpret VSCL, #$003 wz, nr
        if_c_or_nz locknew $000 wz, nr
        if_c_or_nz jmp #$004 wz
        if_c_or_nz locknew $001 wz, nr
        if_c_or_nz jmpret $001, #$004 wz, nr
        if_c_ne_z locknew VSCL wz, nr
        if_c_ne_z jmpret VSCL, #$004 wz, nr
        if_nc_and_nz lockret $000 wz
        if_nc_and_nz jmp #$005 wz
        if_c lockret $001 wz
        if_c jmpret $001, #$005 wz, nr
        if_nc_and_z lockret VSCL wz
        if_nc_and_z jmpret VSCL, #$005 wz, nr
        if_c lockset $000 wz
        if_c jmp #$006 wz
        if_nc_or_z lockset $001 wz
        if_nc_or_z jmpret $001, #$006 wz, nr
        if_c_and_z lockset VSCL wz
        if_c_and_z jmpret VSCL, #$006 wz, nr
        if_c_and_nz lockclr $000 wz
        if_c_and_nz jmp #$007 wz
        if_c_or_z lockclr $001 wz
        if_c_or_z jmpret $001, #$007 wz, nr
        lockclr VSCL wz
        jmpret VSCL, #$007 wz, nr
        if_c_or_nz hubop $000, #$008 wz
        if_c_or_nz jmp #$008 wz
        if_nc_and_z hubop $001, #$008 wz
        if_nc_and_z jmpret $001, #$008 wz, nr
        if_c_and_nz hubop VSCL, #$008 wz
        if_c_and_nz jmpret VSCL, #$008 wz, nr
        if_c_ne_z hubop $000, #$1FF wz
        if_c_ne_z jmp #$1FF wz
        if_never hubop $001, #$1FF wz
        if_never jmpret $001, #$1FF wz, nr
        if_c_and_nz hubop VSCL, #$1FF wz
        if_c_and_nz jmpret VSCL, #$1FF wz, nr
        if_nc_and_z hubop $000, $000 wz, wr
        if_nc_and_z jmpret $000, $000 wz
        if_c hubop $001, $000 wz, wr
        if_c jmpret $001, $000 wz
        if_nz hubop VSCL, $000 wz, wr
        if_nz jmpret VSCL, $000 wz
        if_never hubop $000, $001 wz, wr
        if_never jmpret $000, $001 wz
        if_c hubop $001, $001 wz, wr
        if_c jmpret $001, $001 wz
        if_c_and_z hubop VSCL, $001 wz, wr
        if_c_and_z jmpret VSCL, $001 wz
        if_c hubop $000, $002 wz, wr
        if_c jmpret $000, $002 wz
        if_nc_or_nz hubop $001, $002 wz, wr
        if_nc_or_nz jmpret $001, $002 wz
        hubop VSCL, $002 wz, wr
        jmpret VSCL, $002 wz
        if_nc_and_z hubop $000, $003 wz, wr
        if_nc_and_z jmpret $000, $003 wz
        if_z hubop $001, $003 wz, wr
        if_z jmpret $001, $003 wz
        if_nc_and_z hubop VSCL, $003 wz, wr
        if_nc_and_z jmpret VSCL, $003 wz
        if_nc_and_z hubop $000, $004 wz, wr
        if_nc_and_z jmpret $000, $004 wz
        if_nc hubop $001, $004 wz, wr
        if_nc jmpret $001, $004 wz
        if_nc_and_z hubop VSCL, $004 wz, wr
        if_nc_and_z jmpret VSCL, $004 wz
        if_c hubop $000, $005 wz, wr
        if_c jmpret $000, $005 wz
        if_c_ne_z hubop $001, $005 wz, wr
        if_c_ne_z jmpret $001, $005 wz
        if_c_and_nz hubop VSCL, $005 wz, wr
        if_c_and_nz jmpret VSCL, $005 wz
        if_nc_or_nz hubop $000, $006 wz, wr
        if_nc_or_nz jmpret $000, $006 wz
        if_c_or_nz hubop $001, $006 wz, wr
        if_c_or_nz jmpret $001, $006 wz
        if_nz hubop VSCL, $006 wz, wr
        if_nz jmpret VSCL, $006 wz
        if_nc_and_z hubop $000, $007 wz, wr
        if_nc_and_z jmpret $000, $007 wz
        if_c_or_z hubop $001, $007 wz, wr
        if_c_or_z jmpret $001, $007 wz
        if_nc_or_z hubop VSCL, $007 wz, wr
        if_nc_or_z jmpret VSCL, $007 wz
        if_c_or_nz hubop $000, $008 wz, wr
        if_c_or_nz jmpret $000, $008 wz
        if_nc_or_z hubop $001, $008 wz, wr
        if_nc_or_z jmpret $001, $008 wz
        if_never hubop VSCL, $008 wz, wr
        if_never jmpret VSCL, $008 wz
        if_c_and_nz hubop $000, VSCL wz, wr
        if_c_and_nz jmpret $000, VSCL wz
        if_nc hubop $001, VSCL wz, wr
        if_nc jmpret $001, VSCL wz
        if_nc_and_nz hubop VSCL, VSCL wz, wr
        if_nc_and_nz jmpret VSCL, VSCL wz
        clkset $000 wz, wr
        jmpret $000, #$000 wz
        if_c_and_z clkset $001 wz, wr
        if_c_and_z jmpret $001, #$000 wz
        if_c_and_z clkset VSCL wz, wr
        if_c_and_z jmpret VSCL, #$000 wz
        if_nz cogid $000 wz
        if_nz jmpret $000, #$001 wz
        if_c_ne_z cogid $001 wz
        if_c_ne_z jmpret $001, #$001 wz
        if_nc_and_nz cogid VSCL wz
        if_nc_and_nz jmpret VSCL, #$001 wz
        if_nc_or_z coginit $000 wz, wr
        if_nc_or_z jmpret $000, #$002 wz
        if_nc_or_z coginit $001 wz, wr
        if_nc_or_z jmpret $001, #$002 wz
        if_nc_and_z coginit VSCL wz, wr
        if_nc_and_z jmpret VSCL, #$002 wz
        if_never cogstop $000 wz, wr
        if_never jmpret $000, #$003 wz
        if_c_ne_z cogstop $001 wz, wr
        if_c_ne_z jmpret $001, #$003 wz
        if_nz cogstop VSCL wz, wr
        if_nz jmpret VSCL, #$003 wz
        if_c_eq_z locknew $000 wz
        if_c_eq_z jmpret $000, #$004 wz
        if_never locknew $001 wz
        if_never jmpret $001, #$004 wz
        if_c_ne_z locknew VSCL wz
        if_c_ne_z jmpret VSCL, #$004 wz
        if_z lockret $000 wz, wr
        if_z jmpret $000, #$005 wz
        if_nc_and_nz lockret $001 wz, wr
        if_nc_and_nz jmpret $001, #$005 wz
        if_c lockret VSCL wz, wr
        if_c jmpret VSCL, #$005 wz
        if_nc_and_z lockset $000 wz, wr
        if_nc_and_z jmpret $000, #$006 wz
        if_c_ne_z lockset $001 wz, wr
        if_c_ne_z jmpret $001, #$006 wz
        if_c_or_z lockset VSCL wz, wr
        if_c_or_z jmpret VSCL, #$006 wz
        if_c_ne_z lockclr $000 wz, wr
        if_c_ne_z jmpret $000, #$007 wz
        if_c_and_nz lockclr $001 wz, wr
        if_c_and_nz jmpret $001, #$007 wz
        if_z lockclr VSCL wz, wr
        if_z jmpret VSCL, #$007 wz
        hubop $000, #$008 wz, wr
        jmpret $000, #$008 wz
        if_c_or_z hubop $001, #$008 wz, wr
        if_c_or_z jmpret $001, #$008 wz
        if_nc_or_nz hubop VSCL, #$008 wz, wr
        if_nc_or_nz jmpret VSCL, #$008 wz
        if_z hubop $000, #$1FF wz, wr
        if_z jmpret $000, #$1FF wz
        if_c_or_z hubop $001, #$1FF wz, wr
        if_c_or_z jmpret $001, #$1FF wz
        if_c hubop VSCL, #$1FF wz, wr
        if_c jmpret VSCL, #$1FF wz
        if_nz hubop $000, $000 wz, wc
        if_nz jmp $000 wz, wc
        if_never hubop $001, $000 wz, wc
        if_never jmpret $001, $000 wz, wc, nr
        if_c hubop VSCL, $000 wz, wc
        if_c jmpret VSCL, $000 wz, wc, nr
        if_nz hubop $000, $001 wz, wc
        if_nz jmp $001 wz, wc
        if_c_and_nz hubop $001, $001 wz, wc
        if_c_and_nz jmpret $001, $001 wz, wc, nr
        if_never hubop VSCL, $001 wz, wc
        if_never jmpret VSCL, $001 wz, wc, nr
        if_nc_and_nz hubop $000, $002 wz, wc
        if_nc_and_nz jmp $002 wz, wc
        if_z hubop $001, $002 wz, wc
        if_z jmpret $001, $002 wz, wc, nr
        if_c_ne_z hubop VSCL, $002 wz, wc
        if_c_ne_z jmpret VSCL, $002 wz, wc, nr
        if_nc_or_z hubop $000, $003 wz, wc
        if_nc_or_z jmp $003 wz, wc
        if_nc_and_nz hubop $001, $003 wz, wc
        if_nc_and_nz jmpret $001, $003 wz, wc, nr
        if_nc_and_nz hubop VSCL, $003 wz, wc
        if_nc_and_nz jmpret VSCL, $003 wz, wc, nr
        if_nc_and_z hubop $000, $004 wz, wc
        if_nc_and_z jmp $004 wz, wc
        if_c_and_nz hubop $001, $004 wz, wc
        if_c_and_nz jmpret $001, $004 wz, wc, nr
        if_c hubop VSCL, $004 wz, wc
        if_c jmpret VSCL, $004 wz, wc, nr
        if_never hubop $000, $005 wz, wc
        if_never jmp $005 wz, wc
        if_nc_and_z hubop $001, $005 wz, wc
        if_nc_and_z jmpret $001, $005 wz, wc, nr
        if_c_and_nz hubop VSCL, $005 wz, wc
        if_c_and_nz jmpret VSCL, $005 wz, wc, nr
        if_c hubop $000, $006 wz, wc
        if_c jmp $006 wz, wc
        if_z hubop $001, $006 wz, wc
        if_z jmpret $001, $006 wz, wc, nr
        if_nc hubop VSCL, $006 wz, wc
        if_nc jmpret VSCL, $006 wz, wc, nr
        if_c_and_nz hubop $000, $007 wz, wc
        if_c_and_nz jmp $007 wz, wc
        if_c_or_z hubop $001, $007 wz, wc
        if_c_or_z jmpret $001, $007 wz, wc, nr
        if_c hubop VSCL, $007 wz, wc
        org 0
        if_c jmpret VSCL, $007 wz, wc, nr
        if_never hubop $000, $008 wz, wc
        if_never jmp $008 wz, wc
        if_c_ne_z hubop $001, $008 wz, wc
        if_c_ne_z jmpret $001, $008 wz, wc, nr
        if_never hubop VSCL, $008 wz, wc
        if_never jmpret VSCL, $008 wz, wc, nr
        if_nc hubop $000, VSCL wz, wc
        if_nc jmp VSCL wz, wc
        if_c_eq_z hubop $001, VSCL wz, wc
        if_c_eq_z jmpret $001, VSCL wz, wc, nr
        if_nc_and_z hubop VSCL, VSCL wz, wc
        if_nc_and_z jmpret VSCL, VSCL wz, wc, nr
        if_z clkset $000 wz, wc
        if_z ret wz, wc
        if_never clkset $001 wz, wc
        if_never jmpret $001, #$000 wz, wc, nr
        if_nz clkset VSCL wz, wc
        if_nz jmpret VSCL, #$000 wz, wc, nr
        if_c_eq_z cogid $000 wz, wc, nr
        if_c_eq_z jmp #$001 wz, wc
        if_c_ne_z cogid $001 wz, wc, nr
        if_c_ne_z jmpret $001, #$001 wz, wc, nr
        if_c_eq_z cogid VSCL wz, wc, nr
        if_c_eq_z jmpret VSCL, #$001 wz, wc, nr
        if_nz coginit $000 wz, wc
        if_nz jmp #$002 wz, wc
        if_c_and_nz coginit $001 wz, wc
        if_c_and_nz jmpret $001, #$002 wz, wc, nr
        if_c_and_nz coginit VSCL wz, wc
        if_c_and_nz jmpret VSCL, #$002 wz, wc, nr
        if_c_or_z cogstop $000 wz, wc
        if_c_or_z jmp #$003 wz, wc
        cogstop $001 wz, wc
        jmpret $001, #$003 wz, wc, nr
        if_c_and_nz cogstop VSCL wz, wc
        if_c_and_nz jmpret VSCL, #$003 wz, wc, nr
        if_c_or_z locknew $000 wz, wc, nr
        if_c_or_z jmp #$004 wz, wc
        if_nz locknew $001 wz, wc, nr
        if_nz jmpret $001, #$004 wz, wc, nr
        if_c_ne_z locknew VSCL wz, wc, nr
        if_c_ne_z jmpret VSCL, #$004 wz, wc, nr
        if_nc_or_z lockret $000 wz, wc
        if_nc_or_z jmp #$005 wz, wc
        if_c_and_z lockret $001 wz, wc
        if_c_and_z jmpret $001, #$005 wz, wc, nr
        if_nc lockret VSCL wz, wc
        if_nc jmpret VSCL, #$005 wz, wc, nr
        if_c_and_nz lockset $000 wz, wc
        if_c_and_nz jmp #$006 wz, wc
        if_never lockset $001 wz, wc
        if_never jmpret $001, #$006 wz, wc, nr
        if_nc lockset VSCL wz, wc
        if_nc jmpret VSCL, #$006 wz, wc, nr
        if_c_eq_z lockclr $000 wz, wc
        if_c_eq_z jmp #$007 wz, wc
        if_nc_and_z lockclr $001 wz, wc
        if_nc_and_z jmpret $001, #$007 wz, wc, nr
        if_c_ne_z lockclr VSCL wz, wc
        if_c_ne_z jmpret VSCL, #$007 wz, wc, nr
        if_c_and_z hubop $000, #$008 wz, wc
        if_c_and_z jmp #$008 wz, wc
        if_nc_and_z hubop $001, #$008 wz, wc
        if_nc_and_z jmpret $001, #$008 wz, wc, nr
        if_nc_and_nz hubop VSCL, #$008 wz, wc
        if_nc_and_nz jmpret VSCL, #$008 wz, wc, nr
        if_nc_or_nz hubop $000, #$1FF wz, wc
        if_nc_or_nz jmp #$1FF wz, wc
        if_c_and_z hubop $001, #$1FF wz, wc
        if_c_and_z jmpret $001, #$1FF wz, wc, nr
        if_nz hubop VSCL, #$1FF wz, wc
        if_nz jmpret VSCL, #$1FF wz, wc, nr
        if_c hubop $000, $000 wz, wc, wr
        if_c jmpret $000, $000 wz, wc
        if_c_eq_z hubop $001, $000 wz, wc, wr
        if_c_eq_z jmpret $001, $000 wz, wc
        if_c_eq_z hubop VSCL, $000 wz, wc, wr
        if_c_eq_z jmpret VSCL, $000 wz, wc
        if_nz hubop $000, $001 wz, wc, wr
        if_nz jmpret $000, $001 wz, wc
        if_never hubop $001, $001 wz, wc, wr
        if_never jmpret $001, $001 wz, wc
        if_c_eq_z hubop VSCL, $001 wz, wc, wr
        if_c_eq_z jmpret VSCL, $001 wz, wc
        if_c_and_nz hubop $000, $002 wz, wc, wr
        if_c_and_nz jmpret $000, $002 wz, wc
        if_nc hubop $001, $002 wz, wc, wr
        if_nc jmpret $001, $002 wz, wc
        if_c_and_z hubop VSCL, $002 wz, wc, wr
        if_c_and_z jmpret VSCL, $002 wz, wc
        if_nc_or_z hubop $000, $003 wz, wc, wr
        if_nc_or_z jmpret $000, $003 wz, wc
        if_nc_or_z hubop $001, $003 wz, wc, wr
        if_nc_or_z jmpret $001, $003 wz, wc
        if_c_or_nz hubop VSCL, $003 wz, wc, wr
        if_c_or_nz jmpret VSCL, $003 wz, wc
        if_nc_or_z hubop $000, $004 wz, wc, wr
        if_nc_or_z jmpret $000, $004 wz, wc
        if_c_and_nz hubop $001, $004 wz, wc, wr
        if_c_and_nz jmpret $001, $004 wz, wc
        if_c_and_nz hubop VSCL, $004 wz, wc, wr
        if_c_and_nz jmpret VSCL, $004 wz, wc
        if_c hubop $000, $005 wz, wc, wr
        if_c jmpret $000, $005 wz, wc
        if_c hubop $001, $005 wz, wc, wr
        if_c jmpret $001, $005 wz, wc
        if_nc_or_z hubop VSCL, $005 wz, wc, wr
        if_nc_or_z jmpret VSCL, $005 wz, wc
        if_c_or_z hubop $000, $006 wz, wc, wr
        if_c_or_z jmpret $000, $006 wz, wc
        if_nc_or_nz hubop $001, $006 wz, wc, wr
        if_nc_or_nz jmpret $001, $006 wz, wc
        if_c hubop VSCL, $006 wz, wc, wr
        if_c jmpret VSCL, $006 wz, wc
        if_nc_and_nz hubop $000, $007 wz, wc, wr
        if_nc_and_nz jmpret $000, $007 wz, wc
        if_c_and_nz hubop $001, $007 wz, wc, wr
        if_c_and_nz jmpret $001, $007 wz, wc
        if_nz hubop VSCL, $007 wz, wc, wr
        if_nz jmpret VSCL, $007 wz, wc
        hubop $000, $008 wz, wc, wr
        jmpret $000, $008 wz, wc
        if_c_and_z hubop $001, $008 wz, wc, wr
        if_c_and_z jmpret $001, $008 wz, wc
        if_nc_and_nz hubop VSCL, $008 wz, wc, wr
        if_nc_and_nz jmpret VSCL, $008 wz, wc
        hubop $000, VSCL wz, wc, wr
        jmpret $000, VSCL wz, wc
        if_nc_and_nz hubop $001, VSCL wz, wc, wr
        if_nc_and_nz jmpret $001, VSCL wz, wc
        if_nc hubop VSCL, VSCL wz, wc, wr
        if_nc jmpret VSCL, VSCL wz, wc
        if_c_or_nz clkset $000 wz, wc, wr
        if_c_or_nz jmpret $000, #$000 wz, wc
        clkset $001 wz, wc, wr
        jmpret $001, #$000 wz, wc
        if_z clkset VSCL wz, wc, wr
        if_z jmpret VSCL, #$000 wz, wc
        if_nc_or_z cogid $000 wz, wc
        if_nc_or_z jmpret $000, #$001 wz, wc
        if_nz cogid $001 wz, wc
        if_nz jmpret $001, #$001 wz, wc
        if_nc_or_z cogid VSCL wz, wc
        if_nc_or_z jmpret VSCL, #$001 wz, wc
        coginit $000 wz, wc, wr
        jmpret $000, #$002 wz, wc
        if_c_ne_z coginit $001 wz, wc, wr
        if_c_ne_z jmpret $001, #$002 wz, wc
        if_c_or_nz coginit VSCL wz, wc, wr
        if_c_or_nz jmpret VSCL, #$002 wz, wc
        cogstop $000 wz, wc, wr
        jmpret $000, #$003 wz, wc
        if_c_and_nz cogstop $001 wz, wc, wr
        if_c_and_nz jmpret $001, #$003 wz, wc
        if_never cogstop VSCL wz, wc, wr
        if_never jmpret VSCL, #$003 wz, wc
        if_nc_and_z locknew $000 wz, wc
        if_nc_and_z jmpret $000, #$004 wz, wc
        if_c_and_z locknew $001 wz, wc
        if_c_and_z jmpret $001, #$004 wz, wc
        if_z locknew VSCL wz, wc
        if_z jmpret VSCL, #$004 wz, wc
        if_c_eq_z lockret $000 wz, wc, wr
        if_c_eq_z jmpret $000, #$005 wz, wc
        if_c_ne_z lockret $001 wz, wc, wr
        if_c_ne_z jmpret $001, #$005 wz, wc
        if_nc_or_z lockret VSCL wz, wc, wr
        if_nc_or_z jmpret VSCL, #$005 wz, wc
        if_nc_or_nz lockset $000 wz, wc, wr
        if_nc_or_nz jmpret $000, #$006 wz, wc
        lockset $001 wz, wc, wr
        jmpret $001, #$006 wz, wc
        if_z lockset VSCL wz, wc, wr
        if_z jmpret VSCL, #$006 wz, wc
        lockclr $000 wz, wc, wr
        jmpret $000, #$007 wz, wc
        if_nc_and_z lockclr $001 wz, wc, wr
        if_nc_and_z jmpret $001, #$007 wz, wc
        if_c lockclr VSCL wz, wc, wr
        if_c jmpret VSCL, #$007 wz, wc
        if_nc_and_z hubop $000, #$008 wz, wc, wr
        if_nc_and_z jmpret $000, #$008 wz, wc
        if_c_and_nz hubop $001, #$008 wz, wc, wr
        if_c_and_nz jmpret $001, #$008 wz, wc
        if_nc_and_nz hubop VSCL, #$008 wz, wc, wr
        if_nc_and_nz jmpret VSCL, #$008 wz, wc
        if_nc_and_nz hubop $000, #$1FF wz, wc, wr
        if_nc_and_nz jmpret $000, #$1FF wz, wc
        if_c hubop $001, #$1FF wz, wc, wr
        if_c jmpret $001, #$1FF wz, wc
        if_nc_and_z hubop VSCL, #$1FF wz, wc, wr
        if_nc_and_z jmpret VSCL, #$1FF wz, wc
        nop
        if_never wrbyte $000, $001
        if_nc_and_nz wrbyte $000, $000
        if_nc_and_nz wrbyte $000, $001
        if_nc_and_z wrbyte $000, $000
        if_nc_and_z wrbyte $000, $001
        if_nc wrbyte $000, $000
        if_nc wrbyte $000, $001
        if_c_and_nz wrbyte $000, $000
        if_c_and_nz wrbyte $000, $001
        if_nz wrbyte $000, $000
        if_nz wrbyte $000, $001
        if_c_ne_z wrbyte $000, $000
        if_c_ne_z wrbyte $000, $001
        if_nc_or_nz wrbyte $000, $000
        if_nc_or_nz wrbyte $000, $001
        if_c_and_z wrbyte $000, $000
        if_c_and_z wrbyte $000, $001
        if_c_eq_z wrbyte $000, $000
        if_c_eq_z wrbyte $000, $001
        if_z wrbyte $000, $000
        if_z wrbyte $000, $001
        if_nc_or_z wrbyte $000, $000
        if_nc_or_z wrbyte $000, $001
        if_c wrbyte $000, $000
        if_c wrbyte $000, $001
        if_c_or_nz wrbyte $000, $000
        if_c_or_nz wrbyte $000, $001
        if_c_or_z wrbyte $000, $000
        if_c_or_z wrbyte $000, $001
        wrbyte $000, $000
        wrbyte $000, $001
        if_z neg $128, $032 wz
        long $12EF4F70
        if_c_or_z mov $06B, $049 wz
        long $10C206FB
        if_c hubop $1E9, #$143
        if_c_or_nz muxnz $002, $07B nr
        if_c sumnz $0CF, #$1F3
        if_nc_and_z maxs $0A8, $01E wc
        if_c_and_nz sub $1A6, #$113
        if_nc_or_z rdbyte $173, #$121 wc
        if_c rev FRQA, #$1D7
        negz $180, $041
        long $14063E78
        if_nc mins $0E4, #$00D
        if_nc_or_z ror $12A, $19D wc
        if_c_and_nz sumnc $193, #$112 wz
        if_z rcl $059, $196
        if_nc_or_z movd $02C, #$1EE nr
        if_nc_and_nz shl $171, $0BA nr
        if_nc_and_z rdlong $1AA, #$036 wc
        if_c_and_nz muxnc $0D9, $121 wz, wc
        if_c_and_nz mov $1C8, #$10D wz, nr
        if_c_and_z or $067, DIRB wz, nr
        if_c_and_nz cmpsub $0F3, $053 wc
        if_never max $17C, #$124 wz, wc
        if_c_or_nz addsx $19E, #$0FA wz
        if_nc addsx $098, #$0A3 wc, nr
        if_nz shl $1D0, $14F nr
        if_c tjz $1E1, $09E wr
        if_c_or_nz wrbyte $076, #$0EE wc
        if_c_ne_z neg $06C, #$041
        org 0
        if_nc_and_z cmp $0B8, $0A9 wc
        if_nc rcl $1B5, #$02C wc
        if_nc_and_nz sumnz $010, #$14E wc
        if_c_and_nz sumnz $0F3, $158 wz, nr
        if_nc_or_nz waitvid $11D, #$0E3
        if_c_eq_z addsx $128, #$0E3 wc
        if_nc subsx $0AC, #$05F nr
        if_c_ne_z jmpret $103, #$05D wz
        if_c_and_z or $175, #$189 nr
        if_nc_or_nz sumnz $117, #$01E wc, nr
        if_c_eq_z cmps $034, $137 wc
        if_nz adds $055, $076 nr
        if_never muxc $057, $1DD wc, nr
        if_nc_or_nz max $0F0, #$1BF wz, nr
        if_c muxnc $19B, #$149 wz, wc
        if_nc_or_nz subsx $179, #$076 wz, wc
        if_c_eq_z subx $0F4, $0B7 wz, wc
        if_c_or_nz addabs $1AA, $09A wz, wc, nr
        if_nz rdbyte $05E, $1C1 wz, wc
        if_c_and_nz subx $0A1, #$023
        if_c_or_z absneg $11A, $1B8 wc
        if_nc_or_z movd $0B9, $09B wz, nr
        if_z maxs $154, #$064 wz
        if_c_eq_z movd $182, #$014 wz
        if_c negnz $105, #$00E wz, wc, nr
        if_nc_or_z shl $126, OUTA wz, wc, nr
        if_c_and_nz subs $1CA, #$175
        if_nc_and_z muxnz $1B1, #$0A0 wc, nr
        if_z muxc $09A, $1DA wc, nr
        if_nc_or_nz mov $15A, #$0ED
        if_c_or_z cmpsx $138, #$04F wz, wr
        if_c_ne_z sar $12C, $03C wc, nr
        if_c cmpsub $1AD, $191 wc
        if_nc rol $058, $023 wz, nr
        if_c_and_nz rol $0C8, #$167 wz, wc
        if_nc_or_z rdword $145, $11D wz, wc
        if_z muxz $0F4, #$1D2 wc
        if_c cmpsub $01C, $17F nr
        if_nc_or_nz cmpsub $03A, #$1D4 wz, wc, nr
        if_nc_or_nz sumnz $0C2, #$0EC wc
        if_nz rcl $0E8, #$0CC wz, nr
        if_c_or_nz rev $096, DIRA nr
        if_nc muxz $0C5, $15A wz, wc
        rev $097, #$0A6 wz, wc, nr
        if_nc_and_z rdbyte $0F1, $188 wz, wc
        if_nc_and_z waitpeq $106, $039 wz, wc
        if_c_eq_z negnc $110, #$156 wz
        if_c_and_z maxs $1BF, $11A wz, wc
        if_z neg $088, $04F wz, wc
        if_nc_and_nz ror $0F3, $0D4 wc, nr
        if_c_and_z add $0FD, #$03E wz, wc, nr
        if_c negz $043, $097 nr
        if_c_and_nz rcr $0EF, #$052
        if_nc_or_nz sar $164, #$1D6 wz
        if_c_and_nz sumz $0A6, $15F wc, nr
        if_nc_and_nz waitpne $05D, $0D3 wz, wc, wr
        if_nc_or_nz subx $021, #$186 wc
        if_nc_and_z wrword $050, #$0F9
        if_nc_and_z maxs $060, $0B9 wc
        if_c_ne_z addabs $19F, $09D wz, nr
        if_nc_or_nz cmps $196, #$17A wz, wc, wr
        if_c add $13A, #$003 wz, nr
        if_nc_or_z subsx $1CA, $11A wz, wc
        if_c_or_z subs $012, $13E nr
        if_nc_or_z ror $01F, #$0CA wz
        if_c_or_z maxs $008, #$1F8 wz, wc
        if_nz add $004, #$001 nr
        if_nc addabs $08C, #$001 nr
        if_nc_or_nz movs $10C, VSCL wz
        if_nz subsx $117, #$01C wz, wc, nr
        if_c_and_nz movi $059, $126 wz, wc
        if_nc max $17C, #$1E8 wz, wc, nr
        if_c_or_z rev $080, #$175 nr
        if_never muxc OUTB, #$055 wc, nr
        if_z sub $0E2, #$1DA
        if_never waitcnt $143, #$0DF wc, nr
        if_c_and_z subx $00C, $197 wc
        if_never rdword $188, $0D2 wc
        if_c movd $107, #$115 wc, nr
        if_nc negnz $061, $18E
        if_nc xor $09D, $0C0 wz, wc, nr
        if_nz and $0C8, #$0DD wc
        if_c_eq_z max $0A4, #$060 wz, nr
        long $13EC5319
        if_z waitpne $1CF, #$061 wz
        long $1A32DE26
        if_nc subabs $0AC, $18A wz, wc, nr
        sumnc $04D, $017
        if_z sumnz $05F, #$030 wz, wc, nr
        if_c_or_z tjnz $143, $07D wc, wr
        if_c_or_z mov $01D, #$0A0
        if_z mov $14A, #$043
        if_nc_or_nz subabs $0BC, $0AA wz, nr
        if_z waitvid $0CB, #$027 wc, wr
        if_c xor $169, #$1A3 wz, nr
        long $1D357070
        if_nc_and_z mov $04C, $1A7 nr
        if_c_and_nz or $1E5, #$0F9 wz, wc
        cmps $146, #$1D8 wc, wr
        if_never cmpsub $0F4, $013 wz, wc
        if_z waitvid $144, #$0A8 wz, wr
        if_nc_or_z abs $0FD, #$1F3 wz, nr
        if_nc tjz $19E, $03A wz, wc
        if_c waitcnt CNT, DIRB wz
        long $1F58E8F4
        if_nc_and_nz muxnc $023, $178 wz, wc
        if_c_or_z waitcnt $012, $10F wz, wc, nr
        if_c_or_z shl $02F, #$145 wz, nr
        if_c_or_nz rol $11B, #$13E nr
        if_nc_and_z rcl $047, #$0ED nr
        if_nc_or_z testn $035, #$0E9 wc
        if_z rdlong $0A5, #$08D
        if_nc tjnz CTRA, $10F wz, wr
        if_nc_or_z addabs $0B6, #$0EC wc
        if_c negnz $17E, $109 wz, nr
        if_c_and_z subs $01F, $0E3 wc, nr
        if_z cmpsx $038, #$09B wz, wr
        if_nc_and_nz waitvid $0D1, #$03A wz, wc, wr
        absneg $1C1, #$179
        if_c_or_nz subabs $07E, #$157 wz, wc, nr
        if_c_and_z xor $15E, $141 wz, wc, nr
        if_c_and_nz sumz $179, $1D4 wz
        if_never sumz $01A, $051
        ror $05E, #$0DA wz, nr
        if_c_and_z sumnz $0AC, #$1B5 wc, nr
        if_nc_and_z addabs $19C, $029 wz, wc, nr
        long $1C3D31F1
        if_nc_and_z rol $16B, $145 wz, wc
        if_nc_or_nz addx $123, #$18F nr
        if_nz sar $0C5, #$14D wc, nr
        tjz $054, $03F
        if_nc_and_nz negz $021, #$0EB wc
        long $18A75843
        if_nc_or_z rcr $19B, #$0D2 wz, wc, nr
        long $14474710
        if_nc_or_z ror $143, #$01A
        if_nz sar $055, #$1D9 wz, wc
        cmpsub $0D5, $124 wc
        if_nc mov $092, #$191 wz, wc
        if_never subs $19C, FRQA wc, nr
        if_never max $152, #$1CB wc
        if_nc_or_nz cmps $032, #$1B2 wz, wr
        if_never andn $059, $0C2 wz, wc
        if_c_ne_z add $055, $0DA wz, wc
        if_c negc $090, $19D wz
        if_nc_or_z muxz $19F, #$0FE wz, wc
        if_nc_or_z sumc $0A8, #$138 wz, wc
        if_nc abs OUTA, $045 wz, nr
        if_nc_or_nz subsx $0DE, #$011 wz
        if_never abs $045, #$08E
        if_nc_or_nz cmps $059, $1A1
        if_nc_and_nz cmpsx $0BD, $0F3 wz, wc
        if_nz rdbyte $01E, #$117 wz
        long $1FBB2209
        if_c_and_nz negnz $0EA, #$06D wc, nr
        if_c_or_z hubop $105, #$11F wz, wr
        if_nc_or_nz negc $05C, $1A1 wc
        if_nc_or_z rev $0EC, $047 wc
        long $1E61B146
        if_nc_or_nz movs $13C, PAR wc, nr
        cmpsub $0A3, $1B9 nr
        if_nc_and_z wrbyte $1DA, $0E1 wc
        long $13DE9859
        if_c_and_z negnc $198, $074 wc
        if_nc_and_nz mov $141, #$17C wc
        if_z neg $166, #$120 wz, nr
        if_c_and_z cmpsx $187, #$0E8 wz, wc, wr
        if_c_ne_z tjz $0B3, $00B wz, wc, wr
        if_nc_or_z waitpeq $1A1, #$084 wz
        if_nc_and_nz waitpne $1B3, $168 wr
        cmp $0D2, $0EE wz
        if_c_ne_z waitvid $05B, $1C7 wz, wc
        if_never movi $013, $11B
        if_never rcr $01E, #$070 wz, wc
        if_c and $082, #$0D2 wz
        if_nc_or_z rev $058, $104 wz, wc
        if_nc_or_z test $06E, $15B wc
        if_nc_and_z maxs $0C3, CNT wz, nr
        if_c_ne_z xor $048, $0BE wc
        if_nz muxnc $01C, #$0F5 wz, nr
        if_nc_and_nz cmpsx $1D1, #$16E wz, wc, wr
        long $199EA76C
        if_c_and_z rcl $0F3, #$165 wz, wc
        if_c_eq_z movd $12A, $165 wz, wc, nr
        if_nc_and_nz muxnc $0C2, #$165 wz, wc
        if_c_eq_z subs $144, #$0CF
        if_nc_or_z muxnc $05D, #$16E
        if_never ror $109, #$13C wz, wc, nr
        if_nc_and_nz sar $1AD, PAR wz, nr
        if_c_or_nz rcr $017, #$094 nr
        if_c cmpsub $151, $0A1 wz, wc, nr
        if_nz addx $030, #$02F nr
        if_c_ne_z max $158, $18F nr
        if_c_and_nz min $03B, #$065
        if_c_or_z shl $0C8, FRQB
        if_nz cmpsx $05E, #$0DB
        if_c wrlong $07F, $078 wz, wc
        if_nc_and_nz subabs $042, #$0EE wz, wc, nr
        if_nc_and_z xor $11A, #$19E wz
        if_c_eq_z waitpne $03A, $1E2 wc
        if_c sumnc $07F, #$1E2 wz
        long $12C62C78
        if_nc_or_nz sumc $013, #$0E1
        if_never muxc DIRB, #$0DB
        if_c_or_z wrlong $01C, $0CE wc
        muxc $115, #$1D9 wz
        if_c_and_z jmpret $086, $129 wc
        if_c_eq_z muxz $0C2, #$00D wz
        if_c_and_nz movs $147, $0D0 wz, wc, nr
        if_c_and_nz muxnz $11E, #$1CE
        if_c_and_nz negc $0CE, $10F wc, nr
        if_nc waitcnt $140, #$068 wz, wc
        if_c_ne_z addsx $0CC, #$09F wz, wc
        if_nc_and_nz waitcnt $1CB, #$153 nr
        if_nc_and_nz tjnz $04B, #$074 wz, wr
        if_never muxnc $120, #$17E nr
        if_nc_or_z min $04D, $10F wc, nr
        if_c neg $08B, $1A2 wc
        if_c_and_z mov $136, $052 wz
        if_c_or_z waitcnt $034, $015 wz, wc, nr
        if_c absneg $112, $141 wz, nr
        long $1AE71F96
        long $18BCD028
        if_nc_and_nz adds $10A, #$1BB wz, wc
        if_c_or_nz muxc $0F2, #$06C wc
        if_z sumz $096, $0F6 wc
        long $185EBCD7
        if_c and $078, $18D wc
        long $17A2822B
        if_c_or_z rcr $0CB, #$12D wz, nr
        if_nz waitpeq $184, #$111
        if_nc_or_z sar $0CD, #$0C7 wc, nr
        if_c_eq_z add $0A6, #$1E8 wc
        if_nc_or_nz cmpsub $1DE, #$016 wc
        if_nc hubop $1D1, #$169 wz, wr
        long $1B27F10E
        if_c absneg $146, $0B3
        if_nc_or_z hubop $048, $0C5 wc, wr
        if_nc movd $145, $17B wz, wc
        if_c_and_z wrbyte $1AC, $040 wc
        if_nc_and_nz tjnz $060, #$136 wz
        if_nc_and_nz waitpeq $0EC, #$09E wz
        if_c_ne_z cmpsx $104, #$096 wz
        if_nc_or_z cmpsub $1AC, $079 wz
        addx $1B8, $166 wz, wc
        if_c_ne_z cmpx $0A0, $15C wc
        if_c_ne_z rev $1D8, $046 wz, nr
        if_nc addx $0F4, #$160 wz, nr
        if_c_ne_z sumc $181, #$002 wz, nr
        if_c_and_nz subsx $0E7, #$130 wz, nr
        if_nc_and_nz negnc $143, $0D6 wz
        if_nc_and_nz test $009, $10C wz, wc
        if_nc testn $1E6, $033 wz
        if_c_or_z rev $1C4, $0AF nr
        if_z muxc $00B, #$1BB nr
        if_nc_or_z xor $0C9, #$1B1 wz, wc
        org 0
        if_c_or_nz maxs $01C, #$1FA wz
        if_nc_or_z maxs $170, $051 wc
        if_nc_and_z sumc $116, $14F wc
        if_nz rdlong $101, $0DE
        if_nz subs $04F, #$051 wz, wc, nr
        if_nc_and_nz min $059, $1A5 wz
        sumnc $07C, $136 wc
        if_c_and_nz muxz $133, $0AE wz
        if_c_ne_z addabs $00F, #$175 wc, nr
        if_c max $045, #$09F nr
        if_c_ne_z rdbyte $1BB, $051
        if_c_or_z muxz $150, $0C3
        if_nc_and_z sub $08F, $119 wz
        sumnc $0CC, $086 wz
        long $18B5B662
        if_nc shr $1AD, $093 wz, wc
        if_nc_and_nz max $096, #$04F wz, nr
        if_c_or_z xor $016, #$06A wz, nr
        if_nc_and_nz jmpret $014, $022 wz, wc, nr
        if_c_and_nz sumnz $046, $17F wz, nr
        if_nc rdbyte $1B4, #$1C8
        long $19D521B0
        if_c_and_z sar $0F0, #$114 wz, nr
        if_nc_or_nz or $0F6, #$192 nr
        if_c_ne_z adds CTRB, #$0DE wc
        if_nc muxnz $1CD, $13C nr
        if_z hubop $01C, $004
        if_c_and_z min $1EB, #$099
        if_c_eq_z mins $164, $0CA nr
        if_nc_or_nz rcr $0C8, $15A wz, wc, nr
        if_c muxc $101, $087 wz, wc, nr
        if_nc rdbyte $17B, #$1B9
        if_z mov $1E6, #$139 wc
        if_c_or_z subs $0B3, #$0A7 wz, wc
        if_nc_or_nz waitpeq $00D, $185 wc, wr
        if_nc_and_nz waitcnt $016, $088 wc, nr
        if_c_eq_z addsx $06D, $0F8 wz, wc
        long $188E749E
        cmpsx $031, $0CA
        max $00E, $141
        if_c_or_nz subx $0B4, $0B9
        if_nc abs $19C, #$0EF wz, wc, nr
        if_c_ne_z addabs $185, #$07C wz, nr
        if_nc_and_z sub $090, $0AA wc
        if_never muxz $188, $11D wc
        if_c_and_nz sumnc $0A9, #$017 wz
        if_c_ne_z addsx $0A7, #$1BA wz, wc, nr
        if_c_or_nz movi $0DB, #$0AF wz, wc
        if_never cmpsub $0E1, PHSB wc
        if_c_or_z movd $09F, #$040 wz, nr
        if_c_or_nz addabs $0DA, $0A2 wz, wc, nr
        if_c_ne_z adds $153, #$0B5 wz, wc
        if_nc_or_nz addsx $07B, $016 wc
        if_nc_and_z rdbyte $0CF, #$1B7 wc
        if_nc_and_nz waitpne $085, $0FE wr
        if_z sumc $02D, #$153 wc, nr
        if_c_and_nz min $0C4, #$1DC wc, nr
        if_c_or_nz sumz $02F, $0E6 wz, wc
        if_z waitvid $1E7, $0D1 wz, wc
        if_c_ne_z negnc $161, $0F9 nr
        if_c_or_z cmpsub $0B1, $14E nr
        hubop $048, #$083 wc
        if_c_and_z tjz $111, $1DD wz, wc
        if_nc_and_z waitcnt OUTB, #$134 wc
        if_c_and_nz subsx CNT, #$0AE
        if_nc_or_nz rcl $19B, $05F wz, wc
        if_nc_or_nz cmpsub $115, $196 wc, nr
        if_never add $0A6, $113 wz, wc, nr
        if_nc_and_nz cmpsx $002, #$058 wz, wr
        if_nc_or_z absneg $1D9, $175 wz, wc
        if_never subabs $1E3, $05C wz
        if_nc_or_nz movd $13E, #$196
        if_z negnz $1E2, #$006
        if_c_or_z movi $1EB, VSCL
        if_nz abs $1B5, #$08C wz, wc
        if_c_and_nz neg $1AF, #$096 nr
        if_nc_and_z jmpret $0DE, $0FB
        if_never cmps $0DC, #$1A4 wz
        long $1B452FC4
        if_never jmpret $169, $047 nr
        if_never negz $0FB, $01F wz, wc
        if_nc_and_z max $025, #$13D wc
        if_nc test $130, #$0E6 wc
        if_c_ne_z testn $1BF, $064
        if_nz jmpret $187, $19D wz, nr
        if_c_and_z cmpsx $0E5, #$054 wc, wr
        if_nc addx $1A2, #$099 nr
        if_nc sub $14E, #$15C wz
        if_c_or_nz movi $178, $080 nr
        if_c_or_z waitpne $01F, $1D0 wc
        if_nc cmp $1A5, $0B9 wc
        if_nz tjz $140, #$0A0 wr
        if_nz addsx FRQA, #$072 wc
        if_nc_or_z sumnc $15C, #$0B3 wz, wc, nr
        if_c_ne_z muxnz $133, #$0D7 wz, nr
        long $1C11DF13
        long $1BA13892
        if_nc movi $017, $0B5
        if_c_ne_z negc $08D, $127 wc, nr
        if_c absneg $19D, $189 wz, wc, nr
        if_c_or_nz adds $09E, $0E9 wc
        if_never waitpeq $066, $137 wz
        if_nc_and_z ror $142, #$01A nr
        if_c_ne_z or $182, $1D4 wc
        if_c ror $14F, #$179 wc
        if_nc rcr $015, $1BE wz, wc
        if_c_ne_z abs $018, #$0B7 wz, wc, nr
        if_nc or $126, #$027 wc
        if_c_and_z movi $0C7, $18B wz, wc
        if_nc_or_z shl $0DF, #$02B wz, nr
        if_c addsx $0B2, #$10F nr
        cmps DIRA, #$0CB wc
        if_nc min $1E9, #$18C
        movi $1B6, $029 wz, wc
        if_c rol $113, VSCL wz, wc
        if_nz subsx INA, $0EB
        if_nc_or_nz subx $157, $1C8 wz, wc
        if_never hubop $0A8, #$051 wz, wr
        if_c_and_nz andn $0AD, #$0AB wz
        if_nc_and_z negz $106, #$179 wz
        if_nz movi $0C9, $0FF wc
        if_c addsx $032, #$023 nr
        if_c_and_z cmp $051, $01E wz
        if_c_ne_z or $03F, $0FB wz, wc
        long $152F11AA
        if_never andn $1DD, #$063 wz, wc
        if_nz wrword $127, #$0FB wz, wc
        if_nc addx $0BF, $1B2 wc, nr
        if_nc_and_z movd $1C5, $0B6 wz
        if_c_and_nz muxnc $0A6, $0BC wz
        if_never rdword $104, #$1B6 wz
        if_c_and_z sumc $1DD, #$16B wc, nr
        if_c_or_z rdlong $197, #$0C0 wz, wc
        if_c_or_nz adds $171, $0A4
        if_c subsx $03C, $06B nr
        if_c_and_z addabs $1DE, #$04E wz
        if_nc_and_z abs $19E, #$1D3 wz, nr
        if_nz negnz $0EB, #$0D3 wz
        if_c_eq_z rol $00E, $1D8 wz, wc, nr
        if_z jmpret $035, #$128 wz
        if_c_or_z rol $028, #$140
        if_c_or_nz waitcnt $0CA, $130 wz
        if_nc_or_nz xor $19C, $096 wc, nr
        if_nc_or_z cmpx $060, #$0A3
        if_nc_and_nz waitvid $179, $14A wz
        if_c_and_z movi $091, #$1FB wz
        long $1A1D7C2F
        adds $05D, $18B wz
        if_c_or_z add $0DE, #$0FA wz, wc
        if_nz or $075, #$15C wz, nr
        if_nc_or_nz tjnz $08C, #$078
        if_nc_or_z waitpne $1C7, $01F wz, wc, wr
        if_nc xor $06A, #$136 wc, nr
        jmpret $1C7, #$013 wc, nr
        neg $174, #$056 wz, wc, nr
        if_nc_and_nz rcr $08E, #$1CE
        if_nc_and_nz addx $19C, $051 wz
        if_nc_and_z maxs $098, #$1AE wc
        addsx $124, #$07F wz
        if_c_and_z negz $1CB, #$04A wz, wc
        if_nz lockret $048 wc, wr
        if_nc_or_nz rdword $04E, $168 wz
        if_nc_or_z hubop $0EF, #$131 wz
        if_nc_and_nz subsx $106, #$093 wc, nr
        if_c_and_nz subabs $179, $1BC wz
        if_c_and_z djnz $0A9, #$0C6 wz, wc
        waitpne $17E, #$1DC wc
        if_never negnc $180, #$12E wc, nr
        if_z neg $14E, $0A6 wz, wc
        if_c_or_z muxnc $1D9, #$0EE wz, nr
        if_c_eq_z subsx $0C5, $0A3 nr
        if_c negnc $058, #$078 wc
        if_c_ne_z absneg $10A, #$16C
        if_c_or_z adds $0D9, #$0FD nr
        if_c_or_z rdbyte $183, $1A9
        long $1324D3EF
        if_c_and_nz waitvid $085, $01B wc, wr
        if_c_ne_z sumnz $18C, #$052 wz, wc
        if_z sar $12A, #$039 wz, wc
        long $19A119DD
        if_nc_or_z subabs $0EB, #$157 wz, wc
        if_never sumnz $179, $17B wz
        if_c jmpret $0D1, $100 wz
        if_c_or_nz movi $05B, $1EE nr
        if_nz muxz $156, $047 wc
        if_c_or_z subx CNT, #$101 wc
        if_c_or_z waitcnt $0D5, #$110 wz, wc
        if_z or $159, $1E3 wz, nr
        if_c_ne_z or $0DF, $18A nr
        if_c_or_nz cmpsx $1B7, #$18A wz, wc
        if_nc_and_nz or $150, $135 wz, wc
        if_c_ne_z max $0F1, $0CD wz
        if_nc_or_nz sumc $0AF, $126 nr
        if_z wrbyte $0CC, #$15E wz
        if_c_or_z subs $1E8, #$02C
        if_never wrword $05A, $1CE wz, wc
        if_z mins $094, $12D wz
        long $1A6DC04E
        if_c_eq_z and $086, #$0F0
        if_c_or_z negc $0A0, #$0F8 wc
        if_c_and_nz testn $0D3, #$151
        if_nz subabs $1C0, #$1EF nr
        long $1FF4062E
        if_nz subs $11D, $1EA wz, nr
        if_nc_and_z rol $196, $11B wc
        if_nc_and_nz movd $034, $1E9 wz, nr
        if_nc_or_z sumz $05B, $038 wc
        if_c_and_z wrbyte $04A, #$1E0 wz, wc
        if_c_and_z jmpret $182, $1C7 wc
        if_nc waitvid $0DC, $064 wz, wc, wr
        if_nc_and_nz rol $195, #$0DB wz, wc, nr
        if_c_and_z sumc $055, $182 wz, wc
        if_c waitvid $1EE, #$157 wz
        if_c_and_nz maxs $052, #$1BF wc
        if_nc_and_nz min $0D2, $0C5 wc
        if_c_and_nz jmpret $1CF, $1A6 nr
        if_never min $0FD, #$198 wc, nr
        if_c_or_nz wrword $167, #$164 wz, wc
        if_never rcr $0E7, $1DE wz, wc, nr
        if_nc_or_nz addx $0EA, #$1F7 wz
        if_never wrbyte $161, $1CA wz
        muxnc $0AC, $0E6 wz, wc, nr
        if_z testn $080, $01A
        if_c_or_z rcl $09C, #$0B5 wz, wc, nr
        if_c_ne_z add $168, #$00B wz, wc, nr
        if_c_or_z rcr $0FC, #$108 wc
        long $1A32DABF
        if_nc_or_z sub $14B, #$183 wc
        if_z shl $081, $0EF wz, wc
        if_nc shr $038, #$182 wz, wc, nr
        if_c_and_nz max $03F, $150 wz, wc
        long $1CCE5F9B
        if_c addx $1E9, $114 wc
        if_c_ne_z cmps $0C0, $16A wc, wr
        if_nc_or_z muxz $0F0, #$1E8 wz, wc, nr
        if_nc waitcnt $0E4, $086 nr
        if_c_or_nz rdword $169, $148 wz, wc
        if_nc_and_z abs $197, $030 wz, wc
        if_c negz $1AC, $071 wc
        if_c sub $1C9, $1E8 wc
        if_nc_and_z waitvid $14E, #$1C6 wz, wc, wr
        if_c_ne_z neg $173, FRQB wz, wc
        if_z movs $02C, #$003 nr
        if_c_eq_z muxz $198, $1C5 wz
        if_c_or_z subs $136, $086 wz, wc, nr
        if_nc_and_z tjnz $0B2, #$115 wr
        if_c tjnz $0DF, $023
        if_c_or_z tjz $1C3, $143 wc, wr
        if_nc_or_z hubop $159, $0D7 wc, wr
        if_c_ne_z add $070, #$0FE wz, wc
        if_c_and_z muxc $1DD, $1EE nr
        if_nc_or_nz muxc $193, $084 wc
        if_c_eq_z rdlong $07F, $1D6 wz, wc
        if_nc_or_nz rcr $0D1, $067 wc
        if_c add $01A, $158 wz, wc
        xor $13C, #$168 wz
        org 0
        if_c_ne_z sumnz $0A9, #$0DC wz, nr
        if_c_and_nz negz $034, #$181 nr
        if_nc_or_nz sumnz $103, $0A5 wz
        if_c_or_z cmps $000, #$11A wz, wr
        if_nc abs $000, $085
        if_nc_or_z subx $199, $145 wc
        negnc $147, $047 nr
        if_c_or_nz subsx $182, #$163 wz, wc, nr
        if_nc_or_z mov $1B2, #$10B wc, nr
        if_nc_and_z tjz $0ED, #$1A4
        if_nc_or_nz subx $104, $11B
        if_c_ne_z tjnz $08D, #$1BD wr
        if_nc negz $168, $11A wz
        if_c_and_z waitpeq $0D1, $136 wz, wc
        if_never wrword $115, $14A wz, wc
        if_z shl $131, #$0D3 wz, wc
        if_nc_or_z shl $06D, #$049 wz, wc, nr
        wrbyte $15E, #$1C4 wz, wc
        if_z negz $071, #$0B5 wz
        if_c_or_z tjz $032, #$023 wc, wr
        if_c_and_nz waitcnt $007, #$164 wz, wc, nr
        if_c_and_z rdword $149, $16F
        if_nz mov $1A0, #$145
        if_nc maxs PHSB, $1E8 wc, nr
        if_c_eq_z addabs $1B7, $15C wz, nr
        if_c_eq_z muxc $03E, $000 wz, wc
        if_nc_and_z xor $11C, $0E4
        if_c_or_nz addx $13B, $0C2 wz, nr
        long $152221B8
        if_never tjz $04E, #$104 wz, wr
        if_nc_or_z neg $048, #$147 nr
        if_c muxz $1B0, #$161 wc, nr
        if_nc_and_nz rev $0B3, $15C wz, nr
        if_nz muxnz $023, $1EC wc
        if_c_eq_z ror $194, #$17D wz, wc, nr
        if_c_and_nz sub $172, #$1B3
        if_nc_and_z absneg $186, $07D wz, wc
        if_c_and_z movs $16D, $0A5 wz, nr
        if_nc_and_nz absneg $11D, $06C wz, wc, nr
        if_nc add $053, $08F
        if_nc sumnc $146, $1A0 wz, wc
        long $11824C29
        if_nc_or_nz rol CNT, #$164 wz
        if_never wrbyte $123, #$0E0 wz
        if_c_and_nz wrbyte $0A1, $1B5 wz, wc
        if_c_and_nz testn $1D7, $15F
        if_nc_or_z addx $052, #$112 wz
        if_nc mins $1CD, $09B wc, nr
        if_nc hubop $1E2, #$01A wz, wc
        if_c_or_z movs $18B, $012 wz, wc, nr
        if_c_ne_z tjz $104, #$04C wz, wc, wr
        if_nz subs $171, #$1CD wz, wc, nr
        if_nc_or_z waitcnt $021, $075 wc
        if_never cmpx $1B3, $0C2
        if_nc_and_z jmpret $199, #$18B wc
        if_nc sumnz $1D3, $147 nr
        if_never wrbyte $1A7, #$055 wc
        if_nc_or_z subs $03A, $06A wz
        if_nc_and_nz muxnc $0EF, $00D nr
        if_c_and_nz hubop $07A, $115
        if_c_and_nz min $161, $080 wc
        long $1CFD9672
        if_nc_or_z negz $17B, $0FB wz
        long $171FBADE
        if_nc_or_z addsx CTRA, #$02A wz, wc
        if_nc_or_z cmpsx $044, $119 wc
        if_never tjz $0A3, $190 wc, wr
        if_c_or_z sumz $1E2, $18A wz, wc, nr
        if_c_and_nz adds $173, #$1E3 wc
        if_never abs $11A, #$030 wc, nr
        if_nc addabs $109, $1BD wz, wc, nr
        if_c movs DIRB, #$155 wz, wc, nr
        if_nc_and_z waitvid $05A, #$1D4 wz, wr
        if_nz jmpret INB, $053
        if_nc sumnz $0A8, $1C0
        if_c_or_nz movd $185, $1B2 wz, wc
        if_c_and_nz or $0B9, $02E wz, wc, nr
        if_c_and_nz waitvid $13F, $157
        if_c neg $017, $028 wz, nr
        if_never cmpsx $1DE, #$079 wc
        if_nc_or_nz movs $17C, $19B wz, wc
        absneg $046, #$189 wz
        if_nc_or_z tjnz $1AA, #$115 wc, wr
        if_c_and_nz muxc $08C, #$1A7 wz, wc
        long $106BA333
        if_c hubop $054, #$03D wc
        long $14AC1B42
        if_nc movs $1BA, #$102 wz, nr
        muxz $003, #$104 wc
        if_nc_and_nz negnz $0CF, #$06A nr
        if_z rcr $0E5, #$064 nr
        if_nz rev $168, $0C1 wz
        if_c_eq_z rcr $09F, #$1BA wc
        if_c test $0BD, $0C5 wz, wc
        if_c_and_z adds $001, $18E wz, wc
        if_c_or_nz sumz $1CD, $01F
        if_never rol $06C, $0AD wc
        if_nc_or_nz rcl $1BC, #$1C3 wz, wc, nr
        if_nc_and_nz cmpx $1C9, #$1B4
        if_z rol $07C, #$165 nr
        if_nc rol $0A5, #$1C0 wz
        if_nc_or_z muxz $0C7, #$051 wz, wc, nr
        if_never neg $0BA, $065 wc
        if_nz shl $072, #$1F0 nr
        if_nc_and_nz subsx $1BA, #$03B wz, nr
        if_nc_and_nz adds $18D, $00C wz, wc, nr
        if_c_or_z shl $095, #$0D0 wc, nr
        if_c_or_nz cmp $093, $060 wz, wc
        if_never rol $130, #$0EF wz, wc, nr
        if_never waitcnt $028, #$078 wz, wc
        if_c_and_z absneg $0A9, #$0D1
        if_nc_and_nz max $05D, $10A wc, nr
        if_nc_or_nz mins $1BE, $1D5
        if_c_and_z rcr $000, $1E6 wz, wc
        muxc $177, #$120 wz
        if_nc_or_nz shl $05C, $0D6 wz, wc
        if_c_or_nz shr $114, #$0B3
        if_c_and_z movd $044, $1C6 wz, wc, nr
        if_nc_or_z shr $100, $073
        if_never negc $1AC, #$1B5 wc
        and $124, #$01B wc
        if_nc addx $1DA, $05A wc, nr
        long $15DBC57B
        if_nc_and_z tjnz $0F4, #$0D9 wr
        if_c_or_nz hubop $15F, #$0AC wz, wr
        if_c_and_z movd $026, $0DB wc, nr
        long $122DE2BD
        if_c_or_nz shr $0B6, $13B wz
        if_never abs $028, $1BE wz, wc, nr
        if_nc_and_z addabs $04F, $079 wc
        if_nc muxc $13C, #$18A wc
        cmps $14C, #$1A4 wr
        long $109E6F60
        if_c_and_nz muxc $01E, #$0D8 wc, nr
        if_nc_and_z tjnz $18A, $11F
        if_nz muxc $1D5, #$084 wz, wc
        if_nc_or_z jmpret $053, $1A3 nr
        if_c_eq_z rdlong $191, $00A wz, wc
        if_nc_or_nz mins $195, $169
        if_nc_and_z mov $036, $106 wz, nr
        if_nz sumc $092, #$001 wz, wc, nr
        if_c_or_z rev $18D, #$185 wz, wc, nr
        if_c_and_z negc $0C3, $091
        if_c_or_nz negnz $17E, $189 wc
        if_c_eq_z muxnz $0D6, #$16A wc, nr
        if_nz adds $0FD, $18B wz, nr
        if_c_eq_z subabs $046, $054 wz, nr
        if_c_eq_z sar $0D4, #$032 wz, nr
        if_never rev $04C, $1D4 wc, nr
        if_c_ne_z sumc $0F6, $16D wz
        if_nz add $03F, $194 wc
        wrword $15D, #$0D6 wz, wc
        sumc $03E, #$159
        long $177337EC
        if_nz negc $130, $17A wc
        if_c_and_z addabs $11C, $15F wc, nr
        if_c_and_nz mov $17E, $0A6 wc
        if_z absneg $0D0, #$183 wz, wc, nr
        if_nc_or_nz addx $088, $097 nr
        if_c waitcnt $0CD, #$1CB wz, nr
        test $0B0, #$1CB wz, wc
        if_z subx $144, #$114 wc
        if_c_ne_z waitpne $024, #$139 wz
        if_c_and_nz waitcnt $1B0, $07F wz
        if_nc_or_z waitpne $15F, $19F wz, wr
        mov $08E, $0D0 wz, nr
        long $1DAEBC7C
        if_c_eq_z addx $07D, #$00F wz, wc
        if_nz cmps $115, $14C wz, wc, wr
        xor $099, #$1BB wc, nr
        if_c_and_z rcl $165, $1C3 wz, nr
        if_nc_or_nz testn $0B4, $0C4
        if_nc ror $028, $0BF wz, nr
        if_nc_or_z rol $1E2, $100 wz, wc
        if_nc negz $112, $074 nr
        if_c_and_z and $08D, #$179 wc
        if_c_eq_z subsx $14F, $1EB wc, nr
        if_nc_and_z rdbyte $0C0, $1BB wz, wc
        if_never movi $00D, $0F1 wc, nr
        and $0C6, #$1B5 wz, wc
        if_nc_and_nz negz $07A, $1C2 wz, wc
        if_never cmp $07A, #$132
        wrword $101, #$0A1 wc
        if_never sub $154, $1D7 wz
        if_c_and_nz negc $021, #$07D wz, wc
        if_c addsx $0A5, #$028 wz, wc
        if_c_or_z or $0E7, #$1BB wz, nr
        if_z wrword $09A, #$164 wc
        if_nc_or_nz rdlong $07E, #$1DE wc
        rev $092, $05C wc
        if_nc_or_nz test $1AA, $1D8 wz, wc
        if_nc_and_z ror DIRB, #$050 nr
        if_c_and_nz waitvid $121, #$1A0 wz
        if_nc_or_z negnz $0E3, $1A7 nr
        if_nc_or_z rdbyte $1B3, #$061 wc
        if_c_or_nz ror $050, $0E4 wc, nr
        if_z rev $15F, $0A9 nr
        if_c_or_nz addabs $139, $17A
        if_nc_and_z subsx $0A3, $12F nr
        if_c_ne_z muxc $07A, #$00F
        long $10670581
        if_c_ne_z sumnz $0B3, $15D
        if_c_ne_z mov $163, $13B wz
        negz $105, $1C1 wc
        if_nc_and_nz waitpeq $0FC, #$1DA wc, wr
        if_c_eq_z rcl $037, $02C wz, nr
        if_nc muxnc $0F4, $091 wz, nr
        if_c_or_z abs OUTA, $159 wc
        if_never jmpret $1ED, #$0E4 wc
        if_nc_and_nz rcl $1B6, $0EF wz, wc
        if_nc_or_z muxnz $1AC, $1B6 wz, nr
        if_nc_and_nz cmpsx $02C, #$145 wr
        if_never djnz $1C9, $060 wz, nr
        if_never sumnz $1DA, #$0F5 wc, nr
        if_c_ne_z waitvid $045, $0C7 wz, wc
        if_c_eq_z negc $025, #$020 wc
        if_z absneg $144, $048
        if_c_and_nz sumnc $014, $142 wz, nr
        if_nc_or_z movi $020, #$112 wz, wc, nr
        if_c_ne_z waitvid $036, #$052 wc, wr
        if_nc_or_z addx $11D, $175 nr
        if_c_or_z muxnz $0F6, #$141 wz, wc
        if_nc_or_nz mov $05D, $1DF wz
        if_z subsx $023, #$033 wz, wc, nr
        if_nc_or_nz rol $002, $1CC wc, nr
        if_c movi $035, $13A wz, nr
        if_c_and_nz addabs $1EC, $0AF
        if_nc_or_z movi $095, $1D1 wc, nr
        if_c absneg $079, #$08C
        if_never sumnz $161, $121 wz, nr
        if_nc_or_nz shl $1D0, $00F
        if_nz maxs $0B4, $007 wz
        if_c_ne_z sar $11C, #$000 wz, nr
        min $0A8, #$146
        if_c_or_z movi $027, #$102 wz, wc, nr
        if_c_eq_z negz $062, #$19F wz, wc
        if_c_or_z rdlong $0D1, $024 wc
        if_z shr $121, #$190 nr
        if_c_and_nz maxs $041, #$1C5 wz, nr
        if_nc neg $0C4, $076 nr
        if_c_or_z cmpsub $07A, $0F5 wz, wc, nr
        long $14382A1C
        if_c movd $0DD, #$111 wz
        if_c cmp $149, #$072
        if_nc waitcnt $075, #$165 wc
        if_never muxnc $1A8, #$01F wc, nr
        if_c_and_z movs $178, $1AC wz, wc
        if_nc_and_nz neg $06B, $0EE wz, nr
        if_c_ne_z mov $1EB, $0CD wz
        if_c_or_z addx $1C2, #$11F wc, nr
        if_c muxnz $02F, #$1AA wz, wc, nr
        if_nz movi $0EC, $164 wc
        if_never negnc $183, #$0DB wz, wc
        if_c_or_nz hubop OUTA, $033 wz, wr
        if_nc_and_z rcr $16A, #$1CA wz, wc, nr
        if_nc_or_z or $06A, #$073 wc, nr
        org 0
        if_nc_or_z rdlong $10A, $1DD
        rol $0C7, #$0AB wz, nr
        long $19227CDF
        if_c_eq_z subx $191, $02E wz, wc
        if_z djnz $08E, $07C
        if_c_eq_z max $1E7, $197
        if_c_ne_z tjnz $0E1, $0B1 wc, wr
        if_nc muxnz $04D, $184 nr
        if_nz shr $107, $15B wc, nr
        if_nz ror $1AE, $17D wc, nr
        if_c_ne_z cmp $1D5, #$12A wz
        if_nc_and_nz rdlong $122, $048
        if_nc_or_z rev $0F2, #$184 wc, nr
        if_c_or_z tjz $11F, $112 wr
        if_c_eq_z sar $0F3, $08B wz
        long $1B6897F0
        if_nz rev $135, #$15F wz, nr
        if_nc_and_nz muxz $19D, #$1A6 wz, nr
        if_nc rdword $14A, #$16C wc
        if_never sumz $000, $066
        if_nc_and_z sumz $13D, #$0F3 wz, wc
        if_nc_or_z rcr $0F2, $059 wc
        if_c_or_nz negnc $16C, $1EA nr
        if_nc_and_z muxc $197, #$1EA wc
        if_nc_and_z or $169, #$0D4 wc
        if_c cmpx $13C, #$01C wc
        if_c ror $0F6, $028
        if_nc_and_z waitvid $068, #$023 wr
        mins $034, #$1DE wc, nr
        if_c_or_nz subsx $131, DIRA wc, nr
        if_c_and_nz muxnz $13D, $06B wz, nr
        if_c addabs $06A, $060 nr
        if_c_and_nz addx $140, $1B9 wc, nr
        if_c_or_nz negnc $062, #$0A1 nr
        if_z djnz $10C, $18A wc
        if_nc_or_nz cmpsx $177, #$080 wz
        if_nc sumnz $03D, $03D wc
        if_nc_or_z absneg $153, #$1E5 nr
        if_nz subx $106, $07E
        long $14B0EAB8
        if_c_or_z sumz $0E7, #$08C wz, wc, nr
        if_nc djnz $0B7, #$007 nr
        long $10F65E0B
        if_c_ne_z cmpsub $058, #$161 wz
        if_c_ne_z negnc $10C, $0BD wz, nr
        if_c_eq_z and $18D, $0FC wc
        if_nz cmpx $16E, #$15E wz, wc
        if_nz subs $006, $04B wz
        if_c_or_nz movi $128, #$0A6 wz, nr
        if_c_or_nz sumc $017, #$0BA wc
        if_c_eq_z muxnc $0B9, $02E
        if_nc_and_z addsx $0C4, $064 wc, nr
        long $15239D21
        if_nc_and_z cmpsx $0A0, $0FA wz
        if_nc_or_z waitpne $160, $1A4 wr
        long $176CDA5D
        if_c_or_z maxs $0DF, $02B wc
        if_c_or_nz subs $18F, $1EF wc
        if_c_and_z wrbyte $0AA, #$135 wc
        if_c_and_nz ror $116, #$02F nr
        if_nc_or_z min $01A, #$01A nr
        long $15AB7E74
        if_c_eq_z waitcnt $06A, #$0AE wz, wc, nr
        if_nz ror $053, #$055 wz, wc, nr
        if_c_eq_z addsx $03C, $1DD
        if_nc movs $1AF, #$0F9 wz
        if_nz or $17E, $11A wz
        if_never mov $0E1, #$140 wz
        if_nc_or_nz waitvid $167, $1D2 wz, wc, wr
        if_c_eq_z rev $174, $0CE wc, nr
        if_c_ne_z sumc $171, $16E wz
        if_nc_or_z movd $1CB, #$123 wz
        if_nc_and_nz rev $118, #$19C wz, wc
        if_z add $1DB, $05B wz, wc
        long $1EB4D6E5
        if_c_and_z or $14D, #$01D wz, wc, nr
        if_c_or_z adds $015, $09D wc, nr
        if_c_ne_z addabs $0CE, #$0B2 wz
        if_never andn $0C5, $1E1
        if_nc_and_z tjz $0AF, $17C wc
        if_z ror $1E3, $00C wz, wc, nr
        if_nc_and_z sumz INB, #$172 wz
        if_c_ne_z mov $0BC, #$1A4 nr
        if_nc negc $129, $030 wz, wc
        if_c_and_nz addabs $157, #$0E3 wz, wc
        if_nc_and_z max DIRB, #$0A6 wz, wc
        if_c_or_nz muxnc $1A0, $132 wc, nr
        if_c_or_z sumc $17A, $088 wz, nr
        if_c_or_nz muxnz $1BC, #$1E3 wz, nr
        if_nz xor $0FA, $170 wz, wc, nr
        if_never addsx $0F4, $106 wz, wc
        if_c_and_z addabs $132, #$073 nr
        if_nz add $1A9, $1C2 wz, wc, nr
        if_nc_and_z tjz $148, $023 wc, wr
        if_nc_or_nz cmp $0C5, #$0B1
        if_nc maxs $1CC, $0E1 wz, wc
        if_z djnz $1D9, #$14E nr
        if_never max $154, $196
        if_c_and_nz mov $08F, $012
        if_nc_or_z absneg $1D8, #$1E1 nr
        if_c_and_nz negc $016, #$182 nr
        if_c_and_nz sumz $0F6, #$0CD wz, wc, nr
        if_nc movi $107, $0C1 wc
        long $110ED94E
        if_c_eq_z negnz $007, #$1EE wc
        long $13BF0389
        if_z add $08B, #$1E4 wc
        if_c rcr $077, $135 nr
        if_c testn $159, $03F wc
        long $1D8971BC
        if_nz rdlong $049, $184 wz
        if_z movi INB, #$0C4 wz
        if_c_ne_z djnz $00C, #$110 wc, nr
        if_c_or_nz sumnz PAR, #$052
        if_c_and_nz ror $0E3, $01D wc, nr
        if_nc_and_z cmpsx $1B1, #$0AA
        if_c_or_nz addsx $174, #$011 wz, nr
        if_nz movi $071, #$144 wz, wc
        if_z djnz $0BB, #$0BD wz, wc, nr
        if_z rev $09D, #$096 nr
        if_c_and_z sumnc PAR, #$032 wz, wc
        if_never abs $193, $0A3 wz, wc
        if_c_or_nz movd $19E, $1BB wz, wc, nr
        if_never muxc $081, #$1E2 wc, nr
        if_nc_or_nz rcl $1C4, $123 wz, wc, nr
        if_c_and_z add $128, CTRB wc, nr
        if_c_or_z cmpsx $0CF, #$071 wc
        if_c_ne_z addsx $06E, #$1B2 wc, nr
        if_c_and_z muxz $079, #$0BB nr
        if_c_and_z shl $15D, #$1B0 wc, nr
        if_c_and_z sumnz $00F, $04B wz, wc
        if_c_eq_z sumnc $05A, #$010
        jmpret $15D, $02A wz
        tjnz $006, #$15F wc, wr
        if_c wrlong $199, $15C wc
        if_never addx $1BD, #$190 wz, wc
        if_c_ne_z djnz $01B, #$1DF nr
        if_nc_or_z wrlong $118, #$002 wc
        if_c_and_nz maxs $173, $04B wz, wc
        if_nc_and_z sumc $04B, #$0B3 wz, wc
        if_c_and_z sar $1BC, #$07B wc, nr
        if_z cmpsx $0E4, #$0F4 wc
        long $18BA6CA8
        if_c_and_nz movs $0E7, $059 nr
        if_nz djnz $194, #$0D2 wz, wc, nr
        if_c_eq_z cmpx $1C3, $186 wz, wc
        if_never wrword $18D, #$1F5 wz, wc
        if_c_and_nz absneg $168, #$15E wz
        if_c_or_z wrword $1DA, #$099 wz, wc
        if_nc_or_z sumc $1A8, $098 wz, nr
        waitpeq $1B1, #$02B wz
        if_c_or_z muxnz $086, #$097 wc
        if_c_or_nz negz $0D5, #$188 wz, wc
        if_c_or_nz negnz $12A, $1CF wz, nr
        if_c_and_z mins $0DE, #$1A2 wc
        if_nc_and_nz ror $14E, $096 wz, wc
        long $12765E11
        if_nc_and_nz andn $114, #$1E2 wc
        if_z wrword $012, #$084 wc
        if_nc_or_nz shr $04C, $089 wz, wc
        if_z addx $096, #$00F nr
        long $14636FB9
        if_nc_or_nz movd $145, #$0F4 wc, nr
        if_nc_or_z rcr PHSA, $1CE wz, wc, nr
        if_nc_and_z subs $121, #$17C wc
        if_never min $05D, #$0C5 wz, wc
        if_nz muxz $09E, $0E1 wz, wc, nr
        if_nc_and_nz cmpsx PHSA, $02F
        if_nc_or_z movi $12D, $119 wz, nr
        if_c_eq_z andn $190, #$090 wz
        if_nc_or_nz rcr $08D, $1E8 wz
        if_c_or_nz mov $100, #$18C wz, wc
        if_c muxc $130, $099 nr
        if_nz movs $069, $0F2
        if_c_or_nz sumnc $0B7, $009 wz, wc, nr
        if_z tjz $038, #$07C wz
        long $145D976E
        if_c_eq_z waitvid $14B, INB wc
        if_c_ne_z rcr $17C, #$021 wc
        if_nc_or_nz djnz $131, $16E nr
        if_nc_and_nz negc $1D2, $020 wz, wc
        neg $01A, #$115 wz, nr
        if_c_ne_z muxnc $0A4, $1E2 wz, nr
        if_nc_and_z subs $093, #$0CC wz
        long $1D82206D
        if_c_or_nz neg $180, #$0E0 wz, nr
        if_c_eq_z addsx $0C5, $151 wc, nr
        if_c_or_nz hubop FRQA, #$09A
        if_nc_or_nz cmpsx $1DA, $0DB wz
        if_nc_and_nz sumc $12B, #$1DB wz, nr
        if_c_eq_z adds $1D0, $167 wc
        if_nc_or_z testn $11A, $0C3 wc
        if_nc_and_z shl $098, #$1E3 wz, wc
        if_nc addabs $040, $0C1 wz
        addsx $0D6, $0B7 wc
        if_nc waitpeq $136, $18D wc
        if_c sumc DIRA, #$11C
        if_nz negc $026, #$15B nr
        if_nc_and_z movi $0B6, $04F wc
        if_c min $15C, #$1AA nr
        if_c_or_nz subabs $01B, #$0FA wz, wc, nr

PUB main
