DAT
        org 0
        mov 5, #$200
lab_ret long 0
lab     long 0

PUB main
