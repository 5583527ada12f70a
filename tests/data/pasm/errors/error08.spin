DAT
        org 0
        nop wz
lab_ret long 0
lab     long 0

PUB main
