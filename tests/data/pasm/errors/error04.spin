DAT
        org 0
        ret 5
lab_ret long 0
lab     long 0

PUB main
