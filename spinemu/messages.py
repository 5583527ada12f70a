"""Every message text of the Spin front end and compiler, in the user's words.

Keeping them together keeps the wording consistent and lets tests refer to
them.  Texts are ``str.format`` templates; never put parser-internal names
(``_NL``, ``__ANON_3``) in them: :data:`TOKEN_WORDS` says what to call each
token in "expected ..." messages.
"""
from __future__ import annotations

# ----------------------------------------------------------------------------- files
CANNOT_READ = "cannot read the file: {reason}"
EMPTY_FILE = "the file is empty"
BAD_ENCODING = "the file is not valid UTF-16: {detail}"
OBJECT_NOT_FOUND = "cannot find object file '{name}' (looked in {where})"
DAT_FILE_NOT_FOUND = "cannot find data file '{name}' (looked in {where})"
STANDARD_OBJECT_HINT = ("'{name}' is an object of the Propeller Tool's library (also shipped with PropellerIDE "
                        "and SimpleIDE): put that library's folder in the {var} environment variable or give "
                        "it with -L DIR")
AMBIGUOUS_FILE = ("'{name}' matches several files that differ only in letter case in {folder}: {candidates}; "
                  "spell the name exactly")
NAME_IN_OTHER_CASE = "'{name}' is spelled '{actual}' on disk ({folder}); using it, as the Propeller Tool on Windows would"

DAT_FILE_TOO_BIG = "data file '{name}' is larger than the {size}-byte hub RAM"
OBJECT_RECURSION = "object '{name}' includes itself"

# ----------------------------------------------------------------------------- lexer
UNTERMINATED_BRACE = "the '{{' comment opened on line {line} is never closed with '}}'"
UNTERMINATED_DOC = "the '{{{{' comment opened on line {line} is never closed with '}}}}'"
STRAY_CLOSE_BRACE = "'}' without a '{' to open a comment"
UNTERMINATED_STRING = "this string has no closing '\"'"
BAD_NUMBER = "'{text}' is not a valid number"
BAD_CHARACTER = "unexpected character {ch}"
DESIGNATOR_NOT_FIRST = "'{word}' starts a section and must be in the first column"
HERE_OUTSIDE_DAT = "'$' (the current address) can only be used in a DAT section"
LOCAL_LABEL_OUTSIDE_DAT = "':{name}' is a DAT local label; Spin code cannot use it"

# ----------------------------------------------------------------------------- parser
DEV_SECTION = "DEV sections (precompile/archive) are not supported"
UNEXPECTED = "unexpected {found}{expected}"
EXPECTED_TAIL = "; expected {what}"
SINGLE_EQUAL = "'=' only defines constants (in CON); use ':=' to assign or '==' to compare"
ELSE_COLUMN = "'{word}' must line up with its '{head}' (column {col})"
POST_CONDITION_COLUMN = "'{word}' must line up with its 'repeat' (column {col})"
EMPTY_STRING = "empty string"

#: What to call each token kind in messages ("expected an expression").
TOKEN_WORDS = {
    "NAME": "a name",
    "LOCALNAME": "a local label (:name)",
    "NUMBER": "a number",
    "FLOAT": "a number",
    "STRING": "a string",
    "HERE": "'$'",
    "_NL": "the end of the line",
    "$END": "the end of the file",
    "_INDENT": "an indented block",
    "_DEDENT": "the end of the block",
    "SIZE": "'byte', 'word' or 'long'",
    "BUILTIN": "a built-in command",
    "LOOKUP": "'lookup'",
    "REG": "a register name",
    "KCONST": "a constant",
    "COND": "a condition (if_...)",
    "PASM_OP": "an instruction",
    "EFFECT": "an effect (wz, wc, wr, nr)",
    "OPASSIGN": "an assignment operator",
}
#: What to call a misplaced layout token in "unexpected ..." messages.
FOUND_WORDS = {
    "_NL": "end of line",
    "$END": "end of file",
    "_INDENT": "indentation",
    "_DEDENT": "end of block",
}
#: Token kinds grouped under one phrase in "expected ..." lists.
EXPECTED_GROUPS = [
    ({"IF", "IFNOT", "REPEAT", "CASE", "RETURN", "ABORT", "NEXT", "QUIT"}, "a statement"),
    ({"NAME", "NUMBER", "FLOAT", "STRING", "LPAR", "MINUS", "BANG", "AT", "KCONST"}, "an expression"),
    ({"ASSIGN", "OPASSIGN"}, "an assignment operator"),
    ({"EQEQ", "NE", "LT", "GT", "LE", "GE", "PLUS", "STAR", "SLASH", "AMP"}, "an operator"),
]

# ----------------------------------------------------------------------------- symbols
UNDEFINED = "unknown symbol '{name}'"
DUPLICATE = "'{name}' is already defined (line {line})"
DUPLICATE_SAME_LINE = "'{name}' is already defined"
NOT_A_CONSTANT = "'{name}' is not a constant"
NOT_A_METHOD = "'{name}' is not a method"
NOT_AN_OBJECT = "'{name}' is not an object"
NOT_A_VARIABLE = "'{name}' is not a variable"
UNKNOWN_METHOD_IN_OBJECT = "object '{obj}' has no public method '{name}'"
UNKNOWN_CONSTANT_IN_OBJECT = "object '{obj}' has no constant '{name}'"
WRONG_ARG_COUNT = "'{name}' takes {expected} parameter{s}, not {got}"
RESERVED_NAME = "'{name}' is a reserved word"
NO_PUB = "no PUB method: every object needs one (a program starts with the top object's first)"
NO_METHODS_OR_DAT = "this object has no methods"

# ----------------------------------------------------------------------------- constants
NEEDS_CONSTANT = "this must be a constant expression"
CONSTANT_GROUP = ("{what} is not a constant: in a method, '{word}(' starts a constant expression that takes "
                  "the rest of the expression (as in OpenSpin); put the {word}(...) in parentheses")
CONSTANT_TOO_LATE = ("'{name}' is not known yet here: it is defined further down from constants defined "
                     "further down still (constants are read in two passes); move its definition up")
INTEGER_AND_FLOAT = "cannot mix integer and floating-point values here"
FLOAT_NOT_ALLOWED = "a floating-point value is not allowed here"
DIVIDE_BY_ZERO = "division by zero in a constant expression"
CONSTANT_TOO_BIG = "{value} does not fit in 32 bits"
OVERRIDE_TOO_SMALL = "a '{size}' override in a '{line}' line: a size override may only make items larger"
BAD_COUNT = "the count must be between {low} and {high}, not {value}"
ENUM_NOT_STARTED = "an enumeration needs a '#' start value first"
BAD_CLOCK = "invalid clock setting: {reason}"

# ----------------------------------------------------------------------------- statements
NOT_ASSIGNABLE = "this cannot be assigned to"
NOT_A_STATEMENT = "this expression does nothing; expected an assignment, a call or a command"
NEEDS_VALUE = "'{name}' does not return a value here"
NEXT_OUTSIDE_REPEAT = "'{word}' is only allowed inside a repeat loop"
STRING_TOO_LONG = "strings in expressions must be one character; use string(...)"
ADDRESS_OF_NON_VARIABLE = "'@' needs a variable or a DAT label"
RANGE_NOT_ALLOWED = "a range (..) is only allowed in case values and lookup lists"
METHOD_AS_VALUE = "method '{name}' used where a value is expected"
STRING_CHARACTER_RANGE = "string() characters must be 1 to 255 (strings end with a 0 byte already)"
STRING_NOT_ALLOWED = "string() is not allowed here (this expression is compiled twice)"
OTHER_NOT_LAST = "'other' must be the last case"
LOOKUP_EMPTY = "lookup needs at least one value"
CASE_WITHOUT_MATCH = "case needs at least one match line"
TOO_MANY_NESTED_BLOCKS = ("blocks nested too deeply: Spin allows {limit} levels of if, repeat, case and "
                          "lookup/lookdown (OpenSpin: 'Limit of 8 nested blocks exceeded')")
EXPRESSION_TOO_DEEP = ("expression nested too deeply: spinemu compiles up to {limit} levels (parentheses, "
                       "operators); split it into several statements or constants")
TOO_MANY_PARAMS = "a method can have at most 255 parameters and locals"
LOCALS_TOO_BIG = ("the result, parameters and locals take more than 32 KB "
                  "(OpenSpin: 'Limit of 4096 local variables exceeded')")
FILE_TOO_BIG = "the program, its variables and its stack exceed the 32 KB hub RAM by {longs} longs"
STACK_FREE_TOO_BIG = "_stack and _free must add up to less than 8192 longs"
TOO_MUCH_VAR = "too much VAR space (more than 32 KB)"
OBJECT_COUNT = "an object array must have 1 to 255 elements"
OBJ_TOO_BIG = "object '{name}' is too big ({size} bytes)"
JUMP_TOO_FAR = "this block is too long to jump over"
TOO_MANY_METHODS = "an object can have at most 255 methods and object instances together"
BAD_BUILTIN_USE = "'{name}' cannot be used like this here (wrong place or wrong number of parameters)"
COGNEW_SPIN_OBJECT = "cognew/coginit can only start a method of this object"
BAD_COGNEW = "cognew needs a method call or an address and a parameter"

# ----------------------------------------------------------------------------- DAT / PASM
ORG_RANGE = "org must be between 0 and $1F0, not {value}"
FIT_EXCEEDED = "the code does not fit below ${limit:X} (it reaches ${addr:X})"
LOCAL_LABEL_WITHOUT_GLOBAL = "a local label (:{name}) needs a normal label above it"
PASM_OPERANDS = "'{op}' needs {n} operand{s}"
PASM_RANGE = "operand value ${value:X} is out of range (0..$1FF)"
PASM_UNAVAILABLE = "PASM instructions are not supported yet"
DATA_SIZE_OVERRIDE = "a size override cannot be larger than the data size"
RES_AFTER_DATA = "res cannot be followed by data or instructions in the same org"

# ----------------------------------------------------------------------------- hints (change no byte)
HINT_ASSIGNING_COMPARE = ("'{op}' assigns in Spin: '{target} {op} ...' sets {target} to ({target} {cmp} ...) and gives "
                          "that; to compare '{what}' write '{right}'")
HINT_STALE_JUMP = ("OpenSpin's jump sizing writes this {what} {off} byte{s} {where} (the image is OpenSpin's, "
                   "byte for byte): the compiled program does not do what this line says; moving the code "
                   "around it by a byte (a 'next' or 'quit' that ends exactly 63 bytes on) avoids it")
HINT_ROTATE_NOT_MINUS = ("'{left}<-{right}' rotates {left} left by {right} ('<-' is rotate-left); to compare with "
                         "a negative number write '{left} < -{right}'")
HINT_SHADOWED_OBJECT = ("'{name}' is taken from {used}; {other} is also there and differs (the folder "
                        "listed first wins)")
