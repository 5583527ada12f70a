' Regression: a ** b folds as OpenSpin does, dropping the carry of the middle products
' (found by the program generator)
PUB main
DAT
folded      long $FFFFFFFF ** $FFFFFFFF, $FFFFFFF9 ** $FFFFFFF9, $7FFFFFFF ** $FFFFFFE0
            long -7 ** 3, $12345678 ** $9ABCDEF0, $FFFF0000 ** $FFFF0000, $8000 ** $20000
folded_end
