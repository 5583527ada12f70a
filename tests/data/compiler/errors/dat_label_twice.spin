PUB main
DAT
l1 long 1
l1 long 2
