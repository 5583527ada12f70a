' Regression: x >< n folds with the count n & $FF; past 32 the sign of x fills in
' (found by the program generator)
PUB main
DAT
folded      long $7FFFFFFF >< 33, $80000001 >< 33, $12345678 >< 39, $FFFFFFF9 >< 35
            long $80000001 >< -1, $7FFFFFFF >< -1, $80000001 >< $80000021, 5 >< 256
            long $F0 >< 0, $80000001 >< 63, $12345678 >< 32, $12345678 >< 1
folded_end
