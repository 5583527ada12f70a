'' Drives pin 0, then reboots (CLKSET with bit 7): the run ends there.
PUB main
  dira[0]~~
  reboot
  dira[1]~~
