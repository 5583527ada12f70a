DAT
        org 0
        if_z nop
lab_ret long 0
lab     long 0

PUB main
