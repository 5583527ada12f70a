"""Every message text of the PBASIC front end and interpreter, in one place.

Messages speak the user's language (PBASIC words, never grammar-internal
token names).  Where Parallax's tokenizer reports the same problem, the
wording follows its message so that users can search for it; the numbers in
comments are that tokenizer's error codes (observed with tokenizer 1.30, see
tests/data/README.md).
"""
from __future__ import annotations

# ----------------------------------------------------------------- directives
NO_STAMP = ("unknown target module: no {$STAMP BS2} directive found "
            "(put ' {$STAMP BS2} on the first line)")                      # 156
WRONG_STAMP = ("{{$STAMP {0}}}: spinemu emulates the BASIC Stamp 2 (BS2) only; "
               "the {0} has other timing units and commands")
PBASIC_VERSION = "{{$PBASIC {0}}}: spinemu supports PBASIC 2.0 and 2.5 only"
NEEDS_25 = "'{0}' needs PBASIC 2.5: add ' {{$PBASIC 2.5}} to the top of the file"
NOTHING_TO_TOKENIZE = "nothing to run: the program has no executable statement"   # 157

# ----------------------------------------------------------------- parsing
CANNOT_READ = "cannot read the file: {0}"
UNEXPECTED = "expected {0}, found {1}"
UNEXPECTED_CHAR = "unrecognized character {0!r}"                                  # 103
RESERVED_AS_VALUE = "'{0}' is {1} and cannot be used here"
COMPARE_OUTSIDE_CONDITION = ("'{0}' is only allowed in a condition (IF, ELSEIF, "
                             "DO/LOOP WHILE/UNTIL); in other expressions use the "
                             "bit operators & | ^ ~")
NESTED_INLINE_IF = ("a single-line IF cannot contain another IF; use the "
                    "block form (IF ... THEN / ENDIF)")
OTHER_STAMP_COMMAND = "'{0}' is not a BS2 instruction (it exists on the {1})"
NEXT_WITH_NAME = ("expected ':' or end of line: on the BS2 NEXT takes no "
                  "variable name")                                          # 129
ELSE_AFTER_LABEL = "expected ':' or end of line (use IF ... THEN GOTO label ELSE ...)"

# ----------------------------------------------------------------- preprocessor
PP_UNKNOWN = "unknown conditional-compilation directive '{0}'"
PP_UNBALANCED = "'{0}' without '{1}'"
PP_BAD_EXPR = "cannot evaluate this #IF/#SELECT expression"
PP_ERROR = "#ERROR: {0}"

# ----------------------------------------------------------------- symbols
UNDEFINED = "undefined symbol '{0}'"                                          # 110
DUPLICATE = "symbol '{0}' is already defined"                                 # 123
RESERVED_NAME = "'{0}' is a reserved word and cannot be used as a name"
EXPECTED_CONSTANT = "expected a constant"                                     # 112
EXPECTED_VARIABLE = "expected a variable"
EXPECTED_WORD_VARIABLE = "expected a word variable"                           # 173
EXPECTED_LABEL = "expected a label"                                           # 148
LABEL_AS_VALUE = "'{0}' is a label, not a value"
CONSTANT_TOO_BIG = "constant exceeds 16 bits"                                  # 109
DIVIDE_BY_ZERO = "cannot divide by 0"                                          # 113
OUT_OF_VARIABLE_SPACE = ("out of variable space: {0} needs {1} more bits than "
                         "the 26 bytes of BS2 RAM hold")
ARRAY_SIZE = "array size must be a constant from 1 to {0}"
ARRAY_SIZE_ZERO = "array size cannot be 0"                                             # 125
MODIFIER_UNKNOWN = "expected a variable modifier"                             # 137
MODIFIER_TOO_BIG = "expected a smaller-size variable modifier"                # 139
MODIFIER_RANGE = "variable modifier is out-of-range"                          # 140
MODIFIER_ON_CONSTANT = "a modifier needs a variable, '{0}' is not one"
INDEX_ON_CONSTANT = "'{0}' is not a variable and cannot be indexed"
ALIAS_INDEX = "an alias cannot name an array element; use a modifier"
PIN_RANGE = "pin number must be 0 to 15"                                              # 175
STRING_AS_NUMBER = "a string of {0} characters is not a single value"
EXPRESSION_TOO_COMPLEX = "expression is too complex (the BS2 evaluates on an 8-entry stack)"  # 144

# ----------------------------------------------------------------- structure
WITHOUT = "'{0}' without '{1}'"                                               # 168/169...
MUST_FOLLOW = "'{0}' must be preceded by '{1}'"                              # 228...
EXIT_OUTSIDE_LOOP = "'EXIT' only allowed within FOR-NEXT and DO-LOOP structures"      # 167
ELSE_WITHOUT_IF = "'ELSE' must be preceded by 'IF' or 'CASE'"                        # 159
EXPECTED_CASE = "expected 'CASE'"                                                     # 179
EXPECTED_ENDIF = "expected a label, variable, instruction, or 'ENDIF'"                # 161
NOT_SUPPORTED = "'{0}' is not supported by spinemu yet"
UNDEFINED_LABEL = "undefined label '{0}'"                                             # 111
DUPLICATE_LABEL = "label is already defined"                                          # 117
LABEL_MISSING_COLON = "label is missing ':'"                                          # 174
EXPECTED_BRACKET = "expected '['"                                                     # 121
BUTTON_WORKSPACE = "BUTTON needs a byte or word workspace variable"
TOO_MANY_NESTED = {                                                          # 146 158 163 178
    "FOR": "limit of 16 nested FOR-NEXT loops exceeded",
    "IF": "limit of 16 nested IF-THEN statements exceeded",
    "DO": "limit of 16 nested DO-LOOP statements exceeded",
    "SELECT": "limit of 16 nested SELECT statements exceeded",
}
TOO_MANY_GOSUBS = "limit of 255 GOSUBs exceeded"                                   # 145
TOO_MANY_ELSEIF = "limit of 16 ELSEIF statements within IF structure exceeded"     # 229
TOO_MANY_CASES = "limit of 16 CASE statements within SELECT structure exceeded"    # 181
TOO_MANY_EXITS = "limit of 16 EXIT statements within loop structure exceeded"      # 171
STATEMENTS_AFTER_CASE = "expected statements to follow previous 'CASE'"     # 226

# ----------------------------------------------------------------- DATA / EEPROM
LOCATION_RANGE = "location is out of range (EEPROM is 0 to 2047)"            # 114
LOCATION_USED = "location already contains data"                             # 115

# ----------------------------------------------------------------- arguments
SEROUT_FORMS = ("SEROUT takes Tpin, Baudmode, {Pace,} [data] or "
                "Tpin\\Fpin, Baudmode, {Timeout, Tlabel,} [data]")
SERIN_FORMS = "SERIN takes Rpin{\\Fpin}, Baudmode, {Plabel,} {Timeout, Tlabel,} [data]"
LIST_TOO_LONG = "a {0} list holds at most {1} entries"

# ----------------------------------------------------------------- run time (warnings)
W_OPEN = "[OPEN] "
W_DIV_ZERO = W_OPEN + "division by zero: '/' gives $FFFF and '//' gives the dividend (unverified on hardware)"
W_SHIFT = W_OPEN + "shift by {0} (16 or more) gives 0 (unverified on hardware)"
W_DIG = W_OPEN + "DIG {0}: digits beyond the 5th give 0 (unverified on hardware)"
W_REV = W_OPEN + "REV {0}: REV 0 or above 16 (unverified on hardware)"
W_ATN_HYP = W_OPEN + "ATN/HYP computed from the sign-extended low bytes, rounded (firmware table unverified)"
W_SIN_COS = W_OPEN + "SIN/COS use round(127*sin) (firmware table unverified)"
W_INDEX_WRAP = (W_OPEN + "index runs past the end of the 32-byte RAM: wrapped to "
                "bit {0} (unverified on hardware)")
W_INS_WRITE = W_OPEN + "writing INS has no lasting effect: INS always reads the pins"
W_GOSUB_OVERFLOW = (W_OPEN + "GOSUB nested deeper than 4: the oldest return "
                    "address is overwritten")
W_RETURN_UNDERFLOW = W_OPEN + "RETURN without a pending GOSUB: {0}"
W_RETURN_RESTART = "restarts the program without clearing RAM"
W_RETURN_STALE = "returns to a stale return address"
W_EEPROM_UNDEFINED = ("READ from EEPROM address {0}, which no DATA statement defines: "
                      "reads {1} (on a BS2 it may hold program tokens or old data)")
W_EEPROM_WEAR = ("WRITE to EEPROM address {0} for the {1}th time: real EEPROM wears out "
                 "(about 10^6 writes per cell)")
W_FLOATING = ("[OPEN] reading {0}: undriven input{1} with no stimulus read{2} {3} "
              "(set inputs= or float_level=)")
W_PIN_RANGE = "pin {0} is out of range 0 to 15: uses pin {1}"
W_RANDOM = W_OPEN + "RANDOM uses a documented 16-bit LFSR; the firmware's exact sequence is unverified"
W_INPUT_WAIT = "waiting for {0} input that never comes"
W_FREQOUT = W_OPEN + "FREQOUT/DTMFOUT are recorded as square waves at the tone frequency (the BS2 synthesises sines with fast PWM)"
W_PWM = W_OPEN + "PWM modelled as the BS2 manual describes (carry of an 8-bit duty accumulator, ~4 us per tick); exact tick unverified"
W_WRITE_TIME = W_OPEN + "EEPROM write takes 5 ms per byte in realistic timing (24LC16B maximum; unverified)"
W_GLITCH = (W_OPEN + "outputs released for 18 ms every 2.304 s while asleep or ended "
            "(watchdog period unverified)")
W_FOR_WRAP = (W_OPEN + "the FOR counter wrapped inside its variable: the range test uses the "
              "value read back from the variable, not the 16-bit sum")
