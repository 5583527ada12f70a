PUB main
DAT
  long missing_label
