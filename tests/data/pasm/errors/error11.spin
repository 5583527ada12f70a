DAT
        org 0
        cogid 3, 4
lab_ret long 0
lab     long 0

PUB main
