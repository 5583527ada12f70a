VAR
  long r, n, x, y
PUB main | i
  x := 1000000007
  y := 0
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 0
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 0
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 0
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 0
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 0
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 0
  r := >|x
  x := 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 1
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 1
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294967295
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294967295
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 1
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 1
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1
  r := >|x
  x := (1 << (1 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 3
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 3
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294967293
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294967293
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 2
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 2
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 3
  r := >|x
  x := (1 << (2 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 7
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 7
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294967289
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294967289
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 7
  r := >|x
  x := (1 << (3 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 15
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 15
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294967281
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294967281
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 8
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 8
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 15
  r := >|x
  x := (1 << (4 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 31
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 31
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294967265
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294967265
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 16
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 16
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 31
  r := >|x
  x := (1 << (5 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 63
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 63
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294967233
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294967233
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 32
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 32
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 63
  r := >|x
  x := (1 << (6 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 127
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 127
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294967169
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294967169
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 64
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 64
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 127
  r := >|x
  x := (1 << (7 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 255
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 255
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294967041
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294967041
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 128
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 128
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 255
  r := >|x
  x := (1 << (8 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 511
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 511
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294966785
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294966785
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 256
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 256
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 511
  r := >|x
  x := (1 << (9 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 1023
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 1023
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294966273
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294966273
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 512
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 512
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1023
  r := >|x
  x := (1 << (10 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 2047
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 2047
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294965249
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294965249
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 1024
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 1024
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 2047
  r := >|x
  x := (1 << (11 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 4095
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4095
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294963201
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294963201
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 2048
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 2048
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 4095
  r := >|x
  x := (1 << (12 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 8191
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 8191
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294959105
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294959105
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4096
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4096
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 8191
  r := >|x
  x := (1 << (13 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 16383
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 16383
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294950913
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294950913
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 8192
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 8192
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 16383
  r := >|x
  x := (1 << (14 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 32767
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 32767
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294934529
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294934529
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 16384
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 16384
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 32767
  r := >|x
  x := (1 << (15 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 65535
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 65535
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294901761
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294901761
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 32768
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 32768
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 65535
  r := >|x
  x := (1 << (16 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 131071
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 131071
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294836225
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294836225
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 65536
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 65536
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 131071
  r := >|x
  x := (1 << (17 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 262143
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 262143
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294705153
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294705153
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 131072
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 131072
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 262143
  r := >|x
  x := (1 << (18 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 524287
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 524287
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4294443009
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294443009
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 262144
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 262144
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 524287
  r := >|x
  x := (1 << (19 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 1048575
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 1048575
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4293918721
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4293918721
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 524288
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 524288
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1048575
  r := >|x
  x := (1 << (20 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 2097151
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 2097151
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4292870145
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4292870145
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 1048576
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 1048576
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 2097151
  r := >|x
  x := (1 << (21 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 4194303
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4194303
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4290772993
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4290772993
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 2097152
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 2097152
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 4194303
  r := >|x
  x := (1 << (22 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 8388607
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 8388607
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4286578689
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4286578689
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4194304
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4194304
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 8388607
  r := >|x
  x := (1 << (23 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 16777215
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 16777215
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4278190081
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4278190081
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 8388608
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 8388608
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 16777215
  r := >|x
  x := (1 << (24 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 33554431
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 33554431
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4261412865
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4261412865
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 16777216
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 16777216
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 33554431
  r := >|x
  x := (1 << (25 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 67108863
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 67108863
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4227858433
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4227858433
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 33554432
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 33554432
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 67108863
  r := >|x
  x := (1 << (26 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 134217727
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 134217727
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4160749569
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4160749569
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 67108864
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 67108864
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 134217727
  r := >|x
  x := (1 << (27 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 268435455
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 268435455
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 4026531841
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4026531841
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 134217728
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 134217728
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 268435455
  r := >|x
  x := (1 << (28 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 536870911
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 536870911
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 3758096385
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 3758096385
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 268435456
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 268435456
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 536870911
  r := >|x
  x := (1 << (29 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 1073741823
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 1073741823
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 3221225473
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 3221225473
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 536870912
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 536870912
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1073741823
  r := >|x
  x := (1 << (30 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 2147483647
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 2147483647
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 2147483649
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 2147483649
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 1073741824
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 1073741824
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 2147483647
  r := >|x
  x := (1 << (31 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1000000007
  y := 4294967295
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 4294967295
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 1
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 1
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 1000000007
  y := 2147483648
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := -5
  y := 2147483648
  r := x / y
  r := x // y
  x /= y
  n := x //= y
  x := 4294967295
  r := >|x
  x := (1 << (32 - 1)) | 0
  r := >|x
  n := >|x
  >|x
  x := 1390851128
  y := 4071050724
  r := x * y
  r := x ** y
  r := x -> y
  r := x <- y
  r := x >> y
  r := x << y
  r := x ~> y
  r := x >< y
  r := x #> y
  r := x <# y
  r := x & y
  r := x | y
  r := x ^ y
  r := x + y
  r := x - y
  r := x AND y
  r := x OR y
  r := x < y
  r := x > y
  r := x <> y
  r := x == y
  r := x =< y
  r := x => y
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := x *= y
  x **= y
  n := ^^x
  ^^x
  x := 0
  r := x * y
  r := y * x
  x := 647892279
  y := 1695753998
  r := x * y
  r := x ** y
  r := x -> y
  r := x <- y
  r := x >> y
  r := x << y
  r := x ~> y
  r := x >< y
  r := x #> y
  r := x <# y
  r := x & y
  r := x | y
  r := x ^ y
  r := x + y
  r := x - y
  r := x AND y
  r := x OR y
  r := x < y
  r := x > y
  r := x <> y
  r := x == y
  r := x =< y
  r := x => y
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := x *= y
  x **= y
  n := ^^x
  ^^x
  x := 0
  r := x * y
  r := y * x
  x := 2795742288
  y := 207388624
  r := x * y
  r := x ** y
  r := x -> y
  r := x <- y
  r := x >> y
  r := x << y
  r := x ~> y
  r := x >< y
  r := x #> y
  r := x <# y
  r := x & y
  r := x | y
  r := x ^ y
  r := x + y
  r := x - y
  r := x AND y
  r := x OR y
  r := x < y
  r := x > y
  r := x <> y
  r := x == y
  r := x =< y
  r := x => y
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := x *= y
  x **= y
  n := ^^x
  ^^x
  x := 0
  r := x * y
  r := y * x
  x := 311111475
  y := 3527346212
  r := x * y
  r := x ** y
  r := x -> y
  r := x <- y
  r := x >> y
  r := x << y
  r := x ~> y
  r := x >< y
  r := x #> y
  r := x <# y
  r := x & y
  r := x | y
  r := x ^ y
  r := x + y
  r := x - y
  r := x AND y
  r := x OR y
  r := x < y
  r := x > y
  r := x <> y
  r := x == y
  r := x =< y
  r := x => y
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := x *= y
  x **= y
  n := ^^x
  ^^x
  x := 0
  r := x * y
  r := y * x
  x := 2301595691
  y := 404285457
  r := x * y
  r := x ** y
  r := x -> y
  r := x <- y
  r := x >> y
  r := x << y
  r := x ~> y
  r := x >< y
  r := x #> y
  r := x <# y
  r := x & y
  r := x | y
  r := x ^ y
  r := x + y
  r := x - y
  r := x AND y
  r := x OR y
  r := x < y
  r := x > y
  r := x <> y
  r := x == y
  r := x =< y
  r := x => y
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := x *= y
  x **= y
  n := ^^x
  ^^x
  x := 0
  r := x * y
  r := y * x
  x := 1570621944
  y := 2503055453
  r := x * y
  r := x ** y
  r := x -> y
  r := x <- y
  r := x >> y
  r := x << y
  r := x ~> y
  r := x >< y
  r := x #> y
  r := x <# y
  r := x & y
  r := x | y
  r := x ^ y
  r := x + y
  r := x - y
  r := x AND y
  r := x OR y
  r := x < y
  r := x > y
  r := x <> y
  r := x == y
  r := x =< y
  r := x => y
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := x *= y
  x **= y
  n := ^^x
  ^^x
  x := 0
  r := x * y
  r := y * x
  x := 249103477
  y := 3907149204
  r := x * y
  r := x ** y
  r := x -> y
  r := x <- y
  r := x >> y
  r := x << y
  r := x ~> y
  r := x >< y
  r := x #> y
  r := x <# y
  r := x & y
  r := x | y
  r := x ^ y
  r := x + y
  r := x - y
  r := x AND y
  r := x OR y
  r := x < y
  r := x > y
  r := x <> y
  r := x == y
  r := x =< y
  r := x => y
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := x *= y
  x **= y
  n := ^^x
  ^^x
  x := 0
  r := x * y
  r := y * x
  x := 2179419893
  y := 922121676
  r := x * y
  r := x ** y
  r := x -> y
  r := x <- y
  r := x >> y
  r := x << y
  r := x ~> y
  r := x >< y
  r := x #> y
  r := x <# y
  r := x & y
  r := x | y
  r := x ^ y
  r := x + y
  r := x - y
  r := x AND y
  r := x OR y
  r := x < y
  r := x > y
  r := x <> y
  r := x == y
  r := x =< y
  r := x => y
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := x *= y
  x **= y
  n := ^^x
  ^^x
  x := 0
  r := x * y
  r := y * x
  x := 161042648
  y := 369140570
  r := x * y
  r := x ** y
  r := x -> y
  r := x <- y
  r := x >> y
  r := x << y
  r := x ~> y
  r := x >< y
  r := x #> y
  r := x <# y
  r := x & y
  r := x | y
  r := x ^ y
  r := x + y
  r := x - y
  r := x AND y
  r := x OR y
  r := x < y
  r := x > y
  r := x <> y
  r := x == y
  r := x =< y
  r := x => y
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := x *= y
  x **= y
  n := ^^x
  ^^x
  x := 0
  r := x * y
  r := y * x
  x := 1862494042
  y := 1796035739
  r := x * y
  r := x ** y
  r := x -> y
  r := x <- y
  r := x >> y
  r := x << y
  r := x ~> y
  r := x >< y
  r := x #> y
  r := x <# y
  r := x & y
  r := x | y
  r := x ^ y
  r := x + y
  r := x - y
  r := x AND y
  r := x OR y
  r := x < y
  r := x > y
  r := x <> y
  r := x == y
  r := x =< y
  r := x => y
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := x *= y
  x **= y
  n := ^^x
  ^^x
  x := 0
  r := x * y
  r := y * x
  x := 300026767
  y := 1033639716
  r := x * y
  r := x ** y
  r := x -> y
  r := x <- y
  r := x >> y
  r := x << y
  r := x ~> y
  r := x >< y
  r := x #> y
  r := x <# y
  r := x & y
  r := x | y
  r := x ^ y
  r := x + y
  r := x - y
  r := x AND y
  r := x OR y
  r := x < y
  r := x > y
  r := x <> y
  r := x == y
  r := x =< y
  r := x => y
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := x *= y
  x **= y
  n := ^^x
  ^^x
  x := 0
  r := x * y
  r := y * x
  x := 389609433
  y := 2366729934
  r := x * y
  r := x ** y
  r := x -> y
  r := x <- y
  r := x >> y
  r := x << y
  r := x ~> y
  r := x >< y
  r := x #> y
  r := x <# y
  r := x & y
  r := x | y
  r := x ^ y
  r := x + y
  r := x - y
  r := x AND y
  r := x OR y
  r := x < y
  r := x > y
  r := x <> y
  r := x == y
  r := x =< y
  r := x => y
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := x *= y
  x **= y
  n := ^^x
  ^^x
  x := 0
  r := x * y
  r := y * x
  x := 0
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := >|x
  x := 1
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := >|x
  x := 4294967295
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := >|x
  x := 2
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := >|x
  x := 3
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := >|x
  x := 5
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := >|x
  x := 2147483647
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := >|x
  x := 2147483648
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := >|x
  x := 123456789
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := >|x
  x := 3307312975
  r := -x
  r := !x
  r := ||x
  r := |<x
  r := ^^x
  r := NOT x
  r := >|x
