PUB main
#ifdef FAST
  outa[1] := 1
#else
  outa[2] := 1
#endif
