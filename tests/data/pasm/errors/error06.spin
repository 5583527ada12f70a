DAT
        org 0
        call 5
lab_ret long 0
lab     long 0

PUB main
