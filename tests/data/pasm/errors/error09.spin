DAT
        org 0
        wrlong 3, 4 wr
lab_ret long 0
lab     long 0

PUB main
