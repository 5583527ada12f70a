DAT
        org 0
        rdbyte 3, #4 wz, nr
lab_ret long 0
lab     long 0

PUB main
