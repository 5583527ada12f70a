"""Library programs with parts on the bench: do the Parallax library's objects work unchanged?

Run on demand (``python tests/benchmarks/library_parts.py``): it needs the
Parallax library at ``/opt/oracles/propeller/libraries`` (``--library`` to
point elsewhere).  Nothing of the library is copied: for each object a
top-level program of our own is written to a temporary folder and compiled
with the object's folder on the search path; it runs on the bytecode engine
with parts on the bench, and the parts' view of the run is checked:

* I2C/EEPROM: ``Basic_I2C_Driver_1`` (page write, ACK polling with
  ``WriteWait``, page read) and ``Propeller EEprom`` (``VarBackup``: the
  variables saved into the boot EEPROM come back on the next boot from the
  saved EEPROM);
* LCDs: ``LCD_16x2_4Bit`` (4-bit, timed), ``LCD_16x2_8Bit`` (8-bit, reads the
  busy flag and characters back), ``LCD SPIN driver - 2x16`` (4-bit with
  R/W) and ``Serial_Lcd`` (a Parallax serial LCD through ``Simple_Serial``,
  which it names in lower case: a link with that name stands in for the file
  on a case-sensitive file system);
* servos: ``Servo32v9`` (its pulses come from a PASM cog) and the Boe-Bot
  book's ``CenterServoP12`` (Spin pulses; it prints through a PASM serial
  cog); a build without PASM cogs reports them as needing them.

Prints one line per program: what the parts saw, and PASS or FAIL.  Exit
status 1 if a program that should work does not.
"""
from __future__ import annotations

import argparse
import os
import struct
import sys
import tempfile
import textwrap
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, ROOT)

import spinemu  # noqa: E402
from spinemu.bench import Bench, I2cEeprom, I2cMonitor, Lcd, SerialLcd, Servo  # noqa: E402
from spinemu.compiler import compile_file  # noqa: E402

CLOCK = "CON\n  _clkmode = xtal1 + pll16x\n  _xinfreq = 5_000_000\n"


def program(folder: str, name: str, body: str) -> str:
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        f.write(CLOCK + textwrap.dedent(body))
    return path


def var_longs(prog, hub, count):
    vbase = struct.unpack_from("<H", prog.binary, 8)[0]
    return struct.unpack_from(f"<{count}i", hub, vbase)


def case_basic_i2c(lib, tmp):
    folder = os.path.join(lib, "Basic I2C Driver")
    src = program(tmp, "i2c_top.spin", """
        VAR
          long status[3]
          byte out[32], back[32]
        OBJ
          i2c : "Basic_I2C_Driver_1"
        PUB main | i
          i2c.Initialize(i2c#BootPin)
          repeat i from 0 to 31
            out[i] := i * 7 + 1
          status[0] := i2c.WritePage(i2c#BootPin, i2c#EEPROM, $7000, @out, 32)
          repeat while i2c.WriteWait(i2c#BootPin, i2c#EEPROM, $7000)
            status[1]++
          status[2] := i2c.ReadPage(i2c#BootPin, i2c#EEPROM, $7000, @back, 32)
        """)
    prog = compile_file(src, include_dirs=[folder])
    eeprom, monitor = I2cEeprom(), I2cMonitor()
    result = spinemu.run_spin(prog.binary, parts=[eeprom, monitor], seconds=0.5)
    status = var_longs(prog, result.hub, 3)
    want = bytes((i * 7 + 1) & 0xFF for i in range(32))
    vbase = struct.unpack_from("<H", prog.binary, 8)[0]
    back = result.hub[vbase + 44:vbase + 76]
    ok = status[0] == 0 and status[2] == 0 and back == want and bytes(eeprom.memory[0x7000:0x7020]) == want
    return ok, f"{eeprom.summary()}; {status[1]} ACK polls; read back {'the same' if back == want else 'other'} bytes"


def case_eeprom_varbackup(lib, tmp):
    folder = os.path.join(lib, "Brownout Detector To Save Variables to EEPROM",
                          "Brownout_Demo_-_Archive__Date_2011.10.13__Time_09.56")
    src = program(tmp, "backup_top.spin", """
        VAR
          long boots, stamp
        OBJ
          eeprom : "Propeller EEprom"
        PUB main
          boots++
          stamp := boots * 1000 + 7
          eeprom.VarBackup(@boots, @stamp + 3)
          waitcnt(cnt + clkfreq / 100)
        """)
    prog = compile_file(src, include_dirs=[folder])
    image = prog.eeprom()
    seen = []
    for _ in range(3):
        eeprom = I2cEeprom(data=image)
        result = spinemu.run_spin(image, parts=[eeprom], seconds=0.1)
        seen.append(var_longs(prog, result.hub, 2))
        image = bytes(eeprom.memory)
    ok = seen == [(1, 1007), (2, 2007), (3, 3007)]
    return ok, f"three boots from the saved EEPROM: boots, stamp = {seen}"


def case_lcd_4bit(lib, tmp):
    folder = os.path.join(lib, "Light Dimmer & Triac Driver")
    src = program(tmp, "lcd4_top.spin", """
        OBJ
          lcd : "LCD_16x2_4Bit"
        PUB main
          lcd.START
          lcd.MOVE(1, 1)
          lcd.STR(string("Library LCD"))
          lcd.MOVE(3, 2)
          lcd.DEC(-1234)
        """)
    prog = compile_file(src, include_dirs=[folder])
    lcd = Lcd(rs=0, rw=1, e=2, data=[4, 5, 6, 7])
    spinemu.run_spin(prog.binary, parts=[lcd], seconds=1.0)
    return lcd.text_lines() == ["Library LCD", "  -1234"], lcd.summary()


def case_lcd_8bit(lib, tmp):
    folder = os.path.join(lib, "Stepper Motor Driver (PASM)")
    src = program(tmp, "lcd8_top.spin", """
        VAR
          long got
        OBJ
          lcd : "LCD_16x2_8Bit"
        PUB main
          lcd.START
          lcd.MOVE(1, 1)
          lcd.STR(string("Busy flag read"))
          got := lcd.GetChar(1, 1)
        """)
    prog = compile_file(src, include_dirs=[folder])
    lcd = Lcd(rs=8, rw=9, e=10, data=list(range(8)))
    result = spinemu.run_spin(prog.binary, parts=[lcd], seconds=1.0)
    (got,) = var_longs(prog, result.hub, 1)
    ok = lcd.text_lines()[0] == "Busy flag read" and got == ord("B") and not lcd.warnings
    return ok, f"{lcd.summary()}; GetChar(1, 1) = {got!r}"


def case_lcd_driver_2x16(lib, tmp):
    folder = os.path.join(lib, "4-bit Parallel LCD driver")
    src = program(tmp, "lcd2x16_top.spin", """
        OBJ
          lcd : "LCD SPIN driver - 2x16"
        PUB main
          lcd.start(0, 1, 2, 4)
          lcd.Str(string("2x16 driver"))
        """)
    prog = compile_file(src, include_dirs=[folder])
    lcd = Lcd(e=0, rw=1, rs=2, data=[4, 5, 6, 7])
    spinemu.run_spin(prog.binary, parts=[lcd], seconds=1.0)
    return lcd.text_lines()[0].startswith("2x16 driver"), lcd.summary()


def case_serial_lcd(lib, tmp):
    folder = os.path.join(lib, "4x4 Jameco Keypad Driver")
    src = program(tmp, "serlcd_top.spin", """
        OBJ
          lcd : "Serial_Lcd"
        PUB main
          if lcd.init(5, 9600, 2)
            lcd.cls
            waitcnt(cnt + clkfreq / 100)
            lcd.str(string("Serial LCD"))
            lcd.gotoxy(0, 1)
            lcd.str(string("Simple_Serial"))
        """)
    # Serial_Lcd names "simple_serial"; the file is Simple_Serial.spin (the Propeller Tool runs on
    # case-insensitive file systems): a link with the lower-case name stands in for it
    os.symlink(os.path.join(folder, "Simple_Serial.spin"), os.path.join(tmp, "simple_serial.spin"))
    prog = compile_file(src, include_dirs=[folder, tmp])
    lcd = SerialLcd(pin=5, baud=9600)
    spinemu.run_spin(prog.binary, parts=[lcd], seconds=0.5)
    return lcd.text_lines() == ["Serial LCD", "Simple_Serial"], lcd.summary()


def case_boebot_servo(lib, tmp):
    folder = os.path.join(lib, "Spin Stamp Code for the Boe-Bot")
    servo = Servo(pin=12, pulse_range=(1.0e-3, 2.0e-3))
    result = spinemu.run_spin(os.path.join(folder, "CenterServoP12.spin"), parts=[servo], seconds=0.5)
    widths = {round(p.width / result.trace.clock_hz * 1e3, 2) for p in servo.pulses}
    return len(servo.pulses) > 10 and widths == {1.52}, f"{servo.summary()} ({result.reason})"


def case_servo32(lib, tmp):
    folder = os.path.join(lib, "Servo32 V9")
    src = program(tmp, "servo32_top.spin", """
        OBJ
          servo : "Servo32v9"
        PUB main
          servo.Start
          servo.Set(3, 2000)
          waitcnt(cnt + clkfreq)
        """)
    prog = compile_file(src, include_dirs=[folder])
    servo = Servo(pin=3)
    result = spinemu.run_spin(prog.binary, parts=[servo], seconds=1.0)
    return servo.angle == 180.0, f"{servo.summary()} ({result.reason})"


CASES = [("Basic_I2C_Driver_1", case_basic_i2c, False), ("Propeller EEprom VarBackup", case_eeprom_varbackup, False),
         ("LCD_16x2_4Bit", case_lcd_4bit, False), ("LCD_16x2_8Bit", case_lcd_8bit, False),
         ("LCD SPIN driver - 2x16", case_lcd_driver_2x16, False), ("Serial_Lcd", case_serial_lcd, False),
         ("CenterServoP12 (Boe-Bot)", case_boebot_servo, True), ("Servo32v9", case_servo32, True)]


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--library", default="/opt/oracles/propeller/libraries/community/p1/All")
    args = ap.parse_args(argv)
    if not os.path.isdir(args.library):
        print(f"no library at {args.library}")
        return 2
    pasm = os.path.exists(os.path.join(ROOT, "spinemu", "chip", "pasm_cog.py"))
    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name, case, needs_pasm in CASES:
            t0 = time.perf_counter()
            try:
                ok, what = case(args.library, tmp)
            except Exception as e:          # a library program this emulator cannot run yet: report it
                ok, what = False, f"{type(e).__name__}: {e}"
            wall = time.perf_counter() - t0
            if ok:
                verdict = "PASS"
            elif needs_pasm and not pasm:
                verdict = "needs PASM cogs (not emulated in this build)"
            else:
                verdict = "FAIL"
                failed += 1
            print(f"{name:28} {verdict:8} {wall:5.2f} s  {what}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
