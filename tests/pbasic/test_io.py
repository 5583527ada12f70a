"""BS2 pin, timing and serial commands: what they do to the pins and when.

Times are microseconds (the BS2 trace cycle).  Units from the BASIC Stamp
manual's BS2 quick facts: PULSOUT/PULSIN/RCTIME 2 us, COUNT/FREQOUT ms,
serial bit time = (baudmode & $1FFF) + 20 us, SHIFTOUT 14 us clock pulses.
"""
import pytest

from spinemu.pbasic.serial import format_number

from .conftest import bs2, run


def levels(res, pin):
    return res.trace.pin_levels(pin)


# ------------------------------------------------------------------ digital pins
def test_high_low_toggle_input_output_reverse():
    res = run("HIGH 1\nPAUSE 1\nLOW 1\nPAUSE 1\nTOGGLE 1\nPAUSE 1\nINPUT 1\nPAUSE 1\n"
              "OUTPUT 1\nPAUSE 1\nREVERSE 1\nPAUSE 1\nREVERSE 1\nTOGGLE 2")
    assert levels(res, 1) == [(0, "z"), (0, "1"), (1000, "0"), (2000, "1"), (3000, "z"),
                              (4000, "1"), (5000, "z"), (6000, "1")]
    assert levels(res, 2)[-1] == (6000, "1")


def test_pin_names_from_pin_declarations_reach_the_vcd():
    res = run("Led PIN 9\nHIGH Led\nPAUSE 2\nLed = 0")
    assert levels(res, 9) == [(0, "z"), (0, "1"), (2000, "0")]
    vcd = res.trace.vcd_text()
    assert "$var wire 1 ! Led $end" in vcd and "$timescale 1 us $end" in vcd


def test_pin_arguments_use_their_low_four_bits_and_warn():
    res = run("HIGH 17")
    assert levels(res, 1)[-1] == (0, "1")
    assert any("out of range" in w.message for w in res.warnings)


def test_realistic_high_low_goto_loop_takes_710_us():
    # EME Systems' scope measurement: HIGH, LOW, HIGH, GOTO loop = 710 us.
    res = run("L: HIGH 1\nLOW 1\nHIGH 1\nGOTO L", seconds=0.01, timing="realistic")
    falls = [c for c, v in levels(res, 1) if v == "0"]
    assert falls[1] - falls[0] == 710 and falls[0] == 280


# ------------------------------------------------------------------ time
def test_pause_and_realistic_fetch_time():
    assert run("PAUSE 250").end_cycle == 250_000
    assert run("PAUSE 250", timing="realistic").end_cycle == 300 + 250_000 + 250


def test_nap_and_sleep():
    assert run("NAP 3", seconds=2).end_cycle == 144_000
    assert run("SLEEP 2", seconds=3).end_cycle == 2_000_000


# ------------------------------------------------------------------ pulses
def test_pulsout_inverts_the_pin_for_2_us_units():
    res = run("LOW 3\nPULSOUT 3, 500\nPAUSE 1")
    assert levels(res, 3) == [(0, "z"), (0, "0"), (0, "1"), (1000, "0")]
    res = run("HIGH 3\nPULSOUT 3, 10")
    assert levels(res, 3) == [(0, "z"), (0, "1"), (0, "0"), (20, "1")]


def test_pulsin_measures_a_pulse_in_2_us_units():
    pulse = {2: [(0, 0), (0.010, 1), (0.0115, 0)]}
    res = run("x VAR Word\nPULSIN 2, 1, x", inputs=pulse)
    assert res.var("x") == 750 and res.end_cycle == 11_500
    assert run("x VAR Word\nPULSIN 2, 0, x", inputs=pulse).var("x") == 0   # no low pulse ends


def test_pulsin_times_out_after_131_ms():
    res = run("x VAR Word\nx = 5\nPULSIN 2, 1, x", inputs={2: 0})
    assert res.var("x") == 0 and res.end_cycle == 131_070


def test_rctime_counts_while_the_pin_stays_in_state():
    res = run("x VAR Word\nHIGH 2\nPAUSE 1\nRCTIME 2, 1, x", inputs={2: [(0, 1), (0.0033, 0)]})
    assert res.var("x") == 1150
    assert run("x VAR Word\nRCTIME 2, 1, x", inputs={2: 0}).var("x") == 1


def test_count_counts_cycles_during_the_window():
    res = run("x VAR Word\nCOUNT 2, 100, x", inputs={2: lambda t: int(t * 2000) % 2})
    assert res.var("x") == 100 and res.end_cycle == 100_000


def test_button_debounces_and_branches_once_per_press():
    src = ("w VAR Byte\nn VAR Byte\nDO\nBUTTON 3, 0, 255, 250, w, 1, Pressed\nback:\nPAUSE 10\n"
           "LOOP\nPressed: n = n + 1\nGOTO back")
    res = run(src, seconds=1, inputs={3: [(0, 1), (0.1, 0), (0.3, 1), (0.5, 0)]})
    assert res.var("n") == 2


def test_button_auto_repeats_after_delay_then_every_rate_passes():
    src = ("w VAR Byte\nn VAR Byte\nDO\nBUTTON 3, 1, 5, 2, w, 1, Hit\nback:\nPAUSE 1\nLOOP\n"
           "Hit: n = n + 1\nGOTO back")
    res = run(src, seconds=0.0205, inputs={3: 1})
    # passes 1..20: hit on 1, then after 5 more passes (6), then every 2 (8, 10, ...)
    assert res.var("n") == 1 + 1 + 7


# ------------------------------------------------------------------ sound, PWM
def test_freqout_is_a_square_wave_at_the_tone_frequency():
    res = run("FREQOUT 5, 10, 1000")
    lv = levels(res, 5)
    assert lv[:4] == [(0, "z"), (0, "0"), (0, "1"), (500, "0")]
    assert len([1 for _, v in lv if v == "1"]) == 10 and res.end_cycle == 10_000
    assert lv[-1][1] == "0"
    assert any("[OPEN]" in w.message for w in res.warnings)


def test_freqout_ignores_bit_15_and_zero_is_silence():
    res = run("FREQOUT 5, 10, 32768")
    assert levels(res, 5) == [(0, "z"), (0, "0")] and res.end_cycle == 10_000


def test_dtmfout_plays_each_digit_for_200_ms_then_50_ms_silence():
    res = run("DTMFOUT 5, [1, 2]")
    assert res.end_cycle == 2 * 250_000
    assert levels(res, 5)[-1][1] == "0"


def test_pwm_duty_and_release():
    res = run("PWM 4, 64, 2")
    lv = levels(res, 4)
    highs = sum(1 for _, v in lv if v == "1")
    assert highs == 2 * 64 and lv[-1] == (2 * 256 * 4, "z")


# ------------------------------------------------------------------ serial out
def decode_uart(res, pin, bit_us, inverted=False):
    """Recover bytes from the recorded waveform (start bit, 8 data, stop)."""
    lv = [(c, 1 if v == "1" else 0) for c, v in levels(res, pin) if v != "z"]

    def at(t):
        level = lv[0][1]
        for c, v in lv:
            if c > t:
                break
            level = v
        return level ^ inverted
    out, t, end = bytearray(), -1, res.end_cycle
    while t < end:
        nxt = [c for c, v in lv if c > t and (v ^ inverted) == 0]
        if not nxt:
            break
        start = nxt[0]
        out.append(sum(at(start + bit_us * (i + 1) + bit_us // 2) << i for i in range(8)))
        t = start + bit_us * 10 - bit_us // 2
    return bytes(out)


@pytest.mark.parametrize("mode, inverted", [(84, False), (84 + 0x4000, True), (188, False)])
def test_serout_waveform_decodes_to_the_text(mode, inverted):
    res = run(f"x VAR Byte\nx = 65\nSEROUT 1, {mode}, [\"Hi \", DEC x, CR]")
    assert res.serial_output == {1: b"Hi 65\r"}
    bit = (mode & 0x1FFF) + 20
    assert res.end_cycle == 6 * 10 * bit
    assert decode_uart(res, 1, bit, inverted) == b"Hi 65\r"


def test_serout_open_mode_only_drives_low():
    res = run("SEROUT 1, 84 + $8000, [$55]")
    assert {v for _, v in levels(res, 1)} == {"z", "0"}


def test_serout_pace_waits_between_bytes():
    assert run("SEROUT 1, 84, 5, [\"abc\"]").end_cycle == 3 * 1040 + 2 * 5000


def test_serout_flow_control_waits_for_ready_and_times_out():
    src = "SEROUT 1\\2, 84, 50, Late, [\"ok\"]\nSTOP\nLate: DEBUG \"late\""
    assert run(src, inputs={2: 0}).serial_output == {1: b"ok"}
    res = run(src, inputs={2: 1})
    assert res.debug_output == "late" and res.end_cycle == 50_000


def test_serout_to_pin_16_is_the_debug_port():
    assert run("SEROUT 16, 84, [\"hey\"]").debug_output == "hey"


# ------------------------------------------------------------------ serial in
def test_serin_reads_numbers_strings_and_waits():
    src = ("x VAR Word\ns VAR Byte(4)\nSERIN 1, 84, [WAIT(\"go\"), DEC x, STR s\\3, SKIP 1]\n"
           "DEBUG DEC x, \":\", STR s\\3")
    res = run(src, serial_in={1: b"xxgo123,abcde"})
    assert res.debug_output == "123:abc"
    assert res.end_cycle == len(b"xxgo123,abcd") * 10 * 104


def test_serin_timeout_jumps_to_its_label():
    res = run("x VAR Byte\nSERIN 1, 84, 100, NoData, [x]\nEND\nNoData: DEBUG \"timeout\"")
    assert res.debug_output == "timeout" and res.end_cycle == 100_000


def test_serin_without_timeout_waits_for_good():
    res = run("x VAR Byte\nSERIN 1, 84, [x]\nHIGH 1", seconds=2)
    assert res.reason == "input" and res.end_cycle == 2_000_000
    assert any("never comes" in w.message for w in res.warnings)


def test_serin_flow_control_signals_ready():
    res = run("x VAR Byte\nSERIN 1\\2, 84, [x]", serial_in={1: b"A"})
    assert levels(res, 2) == [(0, "z"), (0, "0"), (1040, "1")]


def test_debugin_formatters():
    src = ("a VAR Word\nb VAR Word\nc VAR Word\nd VAR Word\nDEBUGIN DEC a, SDEC b, IHEX c, BIN d\n"
           "DEBUG DEC a, \" \", SDEC b, \" \", HEX c, \" \", DEC d")
    assert run(src, debug_in="12 -34 $fF 101\r").debug_output == "12 -34 FF 5"
    assert run("a VAR Word\nDEBUGIN DEC2 a", debug_in="12345").var("a") == 12


# ------------------------------------------------------------------ DEBUG
def test_debug_formatters_match_the_manual_examples():
    src = ("x VAR Word\nx = -65\nDEBUG \"Signed: \", SDEC5 x, \" \", ISHEX4 x, \" \", ISBIN16 x, CR\n"
           "DEBUG \"Unsigned: \", DEC5 x, \" \", IHEX4 x, \" \", IBIN16 x")
    assert run(src).debug_output == ("Signed: -00065 -$0041 -%0000000001000001\n"
                                     "Unsigned: 65471 $FFBF %1111111110111111")
    assert format_number("DEC4", 56422) == "6422" and format_number("HEX2", 0xABC) == "BC"


def test_debug_show_value_forms():
    res = run("x VAR Byte\nx = 65\nDEBUG ? x, BIN ? x, ASC ? x, ? x + 1, REP \"*\"\\3, x")
    assert res.debug_output == "x = 65\nx = 1000001\nx = 'A'\nx + 1 = 66\n***A"


def test_debug_str_stops_at_zero_or_takes_n_bytes():
    res = run("s VAR Byte(5)\ns(0) = \"A\"\ns(1) = \"B\"\nDEBUG STR s, \"|\", STR s\\3")
    assert res.debug_bytes == b"AB|AB\x00"


def test_debug_takes_9600_baud_time_only_in_realistic_timing():
    assert run("DEBUG \"0123456789\"").end_cycle == 0
    assert run("DEBUG \"0123456789\"", timing="realistic").end_cycle == 250 + 10417 + 250


def test_debug_terminal_screen_honours_cursor_controls():
    res = run("DEBUG \"hello\", CR, \"world\", CRSRXY, 0, 0, \"J\", CLREOL, HOME, \"Y\"")
    assert res.debug_screen() == ["Y", "world"]


# ------------------------------------------------------------------ shift registers
def test_shiftout_msbfirst_clock_and_data():
    res = run("SHIFTOUT 1, 2, MSBFIRST, [%1011\\4]")
    clock = [c for c, v in levels(res, 2) if v == "1"]
    assert len(clock) == 4 and clock[1] - clock[0] == 60
    data_at_rise = [res.trace.state_at(c)[1] >> 1 & 1 for c in clock]
    assert data_at_rise == [1, 0, 1, 1]


def test_shiftin_samples_the_data_pin():
    res = run("x VAR Byte\nSHIFTIN 1, 2, LSBPRE, [x\\4]", inputs={1: 1})
    assert res.var("x") == 0b1111
    res = run("x VAR Byte\nSHIFTIN 1, 2, MSBPOST, [x]", inputs={1: 0})
    assert res.var("x") == 0


# ------------------------------------------------------------------ inputs
def test_xout_is_reported_as_not_supported():
    from spinemu.diagnostics import SpinError
    with pytest.raises(SpinError, match="'XOUT' is not supported"):
        bs2("XOUT 0, 1, [0\\0]")


def test_optional_watchdog_glitch_after_nap_warns():
    res = run("HIGH 1\nNAP 0\nLOW 1", end_glitch=True)
    assert levels(res, 1) == [(0, "z"), (0, "1"), (18_000, "z"), (36_000, "1"), (36_000, "0")]
    assert any("watchdog" in w.message for w in res.warnings)
