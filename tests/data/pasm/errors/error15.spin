DAT
        org 0
        mov 3, 4 wx
lab_ret long 0
lab     long 0

PUB main
