"""Run robustness cases through ``spinemu.cli.main`` and sort what goes wrong.

Each command line runs in-process, ``main(argv, stdout, stderr)``, in a
fresh work folder, under a budget of CPU seconds per case (``ITIMER_PROF``,
and ten times as many wall-clock seconds; the cycle budget is on the
command line itself, see :mod:`.cases`).  What counts as a finding:

``internal``   exit status 70: the CLI's last-resort guard caught an exception (a bug)
``escaped``    an exception left ``main`` (nothing should)
``status``     an exit status other than 0, 1, 2, 70
``silent``     status 1 or 2 with nothing printed at all
``traceback``  a Python traceback printed although the status is not 70
``bad-python`` a module written by ``spinemu translate`` that ``compile()`` rejects
``wrong-line`` an error message quoting a source line that is not the line its ``file:line`` names
``py-warning`` a Python warning (not a deprecation) reached the user: matplotlib's, numpy's...
``stray-output`` text written to the process's own stdout/stderr instead of the streams ``main`` got
``timeout``    the case ran past its time budget (reported apart: slow is not a crash)

Findings are grouped by *signature*: the kind, the exception type and the
innermost spinemu function of its traceback (the guard prints the traceback
because the runner sets ``SPINEMU_TRACEBACK=1``).
"""
from __future__ import annotations

import contextlib
import io
import os
import re
import shutil
import signal
import sys
import tempfile
import time
import unicodedata
import warnings
from collections import Counter
from dataclasses import dataclass, field
from typing import Optional

from .cases import Case, make_case

__all__ = ["Finding", "Campaign", "run_case", "run_campaign", "CaseTimeout", "BAD_KINDS"]

#: Finding kinds that fail a campaign (``timeout`` is reported but does not fail it).
BAD_KINDS = ("internal", "escaped", "status", "silent", "traceback", "bad-python", "wrong-line", "py-warning",
             "stray-output")


class CaseTimeout(BaseException):
    """The wall-clock budget of a case ran out (a BaseException: the CLI's guard must not catch it)."""


@dataclass
class Finding:
    """One thing that went wrong in one command of one case."""

    kind: str
    seed: int
    case_kind: str
    argv: list
    status: Optional[int]
    signature: str
    detail: str
    forced: bool = False

    def reproduce(self) -> str:
        """The command line that rebuilds and reruns this case and prints what it does."""
        kind = f" --kind {self.case_kind}" if self.forced else ""
        return f"python -m tests.fuzz.robust --seed {self.seed}{kind} --show"


@dataclass
class Campaign:
    """What a campaign ran and found."""

    first_seed: int
    cases: int = 0
    commands: int = 0
    statuses: Counter = field(default_factory=Counter)
    kinds: Counter = field(default_factory=Counter)
    kind_statuses: Counter = field(default_factory=Counter)     # (case kind, command, status) -> count
    findings: list = field(default_factory=list)
    seconds: float = 0.0

    @property
    def bad(self) -> list:
        return [f for f in self.findings if f.kind in BAD_KINDS]

    def signatures(self) -> dict:
        """``{signature: [findings]}``, failing kinds first."""
        out: dict = {}
        for f in sorted(self.findings, key=lambda f: (f.kind not in BAD_KINDS, f.signature)):
            out.setdefault(f.signature, []).append(f)
        return out


_FRAME = re.compile(r'File "([^"]+)", line (\d+), in (\S+)')


def _signature(kind: str, text: str) -> str:
    """``kind: ExceptionType at spinemu/module.py:function`` from a printed traceback."""
    frames = _FRAME.findall(text)
    ours = [f for f in frames if "/spinemu/" in f[0].replace("\\", "/")]
    where = ""
    if ours:
        path, _line, func = ours[-1]
        where = " at spinemu/" + path.replace("\\", "/").rsplit("/spinemu/", 1)[1] + ":" + func
    m = re.search(r"internal error: ([A-Za-z_.]+)", text)
    exc = m.group(1) if m else ""
    return f"{kind}: {exc}{where}".strip()


def _timeout(signum, frame):
    raise CaseTimeout()


def _write_files(case: Case, workdir: str) -> None:
    with open(os.path.join(workdir, "in.txt"), "wb") as fh:     # what --console-in sends, in every case
        fh.write(b"12\r-7\rhello\r\x00\xff")
    for name, data in case.files.items():
        path = os.path.join(workdir, name)
        if name.endswith("/"):
            os.makedirs(path, exist_ok=True)
            continue
        os.makedirs(os.path.dirname(path) or workdir, exist_ok=True)
        with open(path, "wb") as fh:
            fh.write(data)


def _argv(argv: list, workdir: str) -> list:
    return [a.replace("{dir}", workdir) for a in argv]


_DIAG = re.compile(r"^(?P<path>.+?):(?P<line>\d+):(?P<col>\d+): (?:error|warning): ")


def _file_lines(path: str, trace: bool = False) -> Optional[list]:
    """A file's lines as spinemu reads it: sources UTF-16 with a BOM, else UTF-8, else Latin-1
    (Spin) or Windows-1252 (PBASIC); trace logs UTF-8 with replacement characters."""
    try:
        with open(path, "rb") as fh:
            data = fh.read()
    except OSError:
        return None
    spin = path.lower().endswith(".spin")
    if trace or not spin and not path.lower().endswith((".bs2", ".bs1", ".pbasic", ".bas")):
        text = data.decode("utf-8", "replace")                  # trace logs and anything else
    elif data.startswith((b"\xff\xfe", b"\xfe\xff")):
        text = data.decode("utf-16", "replace")
    else:
        data = data[3:] if data.startswith(b"\xef\xbb\xbf") else data
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError:
            text = data.decode("latin-1" if spin else "cp1252", "replace")
    return re.split(r"\r\n|\r|\n", text)


def _visible(text: str) -> str:
    """What a diagnostic shows of a source line: control characters (but tabs) as U+FFFD."""
    return "".join("\ufffd" if ch != "\t" and unicodedata.category(ch) in ("Cc", "Cs", "Zl", "Zp") else ch
                   for ch in text)


def _wrong_source_lines(err: str, workdir: str, trace: bool = False) -> list:
    """Diagnostics in ``err`` about a file of the case whose quoted source line is not that line of the file."""
    out, files = [], {}             # each file read once: an error list can name it thousands of times
    lines = err.splitlines()
    for i, text in enumerate(lines[:-1]):
        m = _DIAG.match(text)
        if not m or not m.group("path").startswith(workdir) or not lines[i + 1].strip():
            continue
        caret = lines[i + 2] if i + 2 < len(lines) else ""
        if not caret.strip().startswith("^"):
            continue                                  # no source line quoted
        path = m.group("path")
        if path not in files:
            files[path] = _file_lines(path, trace)
        source = files[path]
        n = int(m.group("line"))
        if source is None or not 1 <= n <= len(source):
            continue
        quoted, actual = lines[i + 1].rstrip(), _visible(source[n - 1]).rstrip()
        if quoted.startswith("...") or quoted.endswith("..."):     # a long line, shown around the column
            cut = quoted[3 if quoted.startswith("...") else 0: -3 if quoted.endswith("...") else None]
            if cut.rstrip() in actual:
                continue
        if quoted != actual:
            out.append(f"{text}\n  quoted: {quoted[:120]!r}\n  line {n}: {actual[:120]!r}")
    return out


def _check_python(case: Case, workdir: str) -> list:
    out = []
    for folder in case.python_dirs:
        folder = folder.replace("{dir}", workdir)
        if not os.path.isdir(folder):
            continue
        for name in sorted(os.listdir(folder)):
            if not name.endswith(".py"):
                continue
            path = os.path.join(folder, name)
            with open(path, "rb") as fh:
                source = fh.read()
            try:
                compile(source, path, "exec")
            except (SyntaxError, ValueError) as e:
                out.append(f"{name}: {type(e).__name__}: {e}")
    return out


def run_case(case: Case, budget_s: float = 20.0, workdir: Optional[str] = None, show=None) -> tuple:
    """Run every command of ``case``; return ``(findings, statuses)``.

    Args:
        case: the case.
        budget_s: CPU seconds for the whole case (0: none).
        workdir: a folder to use (kept); default a fresh temporary one (removed).
        show: a callable that receives a text report of each command, for ``--show``.
    """
    from spinemu.cli import main

    own = workdir is None
    workdir = workdir or tempfile.mkdtemp(prefix="spinemu-robust-")
    os.makedirs(workdir, exist_ok=True)
    findings, statuses = [], []
    old_env = os.environ.get("SPINEMU_TRACEBACK")
    os.environ["SPINEMU_TRACEBACK"] = "1"
    old_stdin, sys.stdin = sys.stdin, io.StringIO()     # --console must not take over a terminal
    # the budget is CPU seconds (ITIMER_PROF: a loaded machine does not make a case "slow"),
    # with ten times as many wall-clock seconds for a case that blocks without using the CPU (on a loaded
    # machine a case of a few CPU seconds can take a hundred wall-clock seconds)
    use_alarm = budget_s > 0 and hasattr(signal, "setitimer")
    old_handlers = [(sig, signal.signal(sig, _timeout)) for sig in (signal.SIGPROF, signal.SIGALRM)] \
        if use_alarm else []
    try:
        _write_files(case, workdir)
        if use_alarm:
            signal.setitimer(signal.ITIMER_PROF, budget_s)
            signal.setitimer(signal.ITIMER_REAL, 10 * budget_s)
        for raw in case.commands:
            argv = _argv(raw, workdir)
            out, err = io.StringIO(), io.StringIO()
            stray = io.StringIO()                     # what bypasses the streams main() was given
            status, kind, detail = None, None, ""
            with warnings.catch_warnings(record=True) as caught, \
                    contextlib.redirect_stdout(stray), contextlib.redirect_stderr(stray):
                warnings.simplefilter("always")
                try:
                    status = main(argv, out, err)
                except CaseTimeout:
                    kind, detail = "timeout", f"ran past {budget_s} s"
                except BaseException as e:  # noqa: BLE001 - that is what the fuzzer looks for
                    import traceback
                    kind, detail = "escaped", "".join(traceback.format_exception(type(e), e, e.__traceback__))
            text = out.getvalue() + err.getvalue()
            shown = [w for w in caught if not issubclass(w.category, (DeprecationWarning, PendingDeprecationWarning))]
            if kind is None and shown:
                w = shown[0]
                kind, detail = "py-warning", f"{w.category.__name__}: {w.message} ({w.filename}:{w.lineno})"
            if kind is None and stray.getvalue().strip():
                kind, detail = "stray-output", stray.getvalue()[-2000:]
            if kind is None:
                if status == 70:
                    kind, detail = "internal", err.getvalue()
                elif status not in (0, 1, 2):
                    kind, detail = "status", text
                elif status in (1, 2) and not text.strip():
                    kind = "silent"
                elif "Traceback (most recent call last)" in text:
                    kind, detail = "traceback", text
                elif status == 1:
                    wrong = _wrong_source_lines(err.getvalue(), workdir, raw[0] in ("trace", "sidebyside"))
                    if wrong:
                        kind, detail = "wrong-line", "\n".join(wrong)
            statuses.append(status)
            if show:
                show(argv, status, out.getvalue(), err.getvalue())
            if kind:
                sig = _signature(kind, detail) if kind in ("internal", "escaped", "traceback") else \
                    f"{kind}: {detail.split(' (')[0][:80]}" if kind == "py-warning" else \
                    f"{kind}: {' '.join(raw[:2])}"
                findings.append(Finding(kind, case.seed, case.kind, argv, status, sig, detail[-3000:], case.forced))
                if kind == "timeout":
                    break
        _stop_timers(use_alarm)
        for problem in _check_python(case, workdir):
            findings.append(Finding("bad-python", case.seed, case.kind, _argv(case.commands[0], workdir), None,
                                    "bad-python: " + problem.split(":", 2)[1].strip(), problem, case.forced))
    except CaseTimeout:
        findings.append(Finding("timeout", case.seed, case.kind, _argv(case.commands[0], workdir), None,
                                f"timeout: {' '.join(case.commands[0][:2])}", f"ran past {budget_s} s",
                                case.forced))
    finally:
        _stop_timers(use_alarm)
        for sig, handler in old_handlers:
            signal.signal(sig, handler)
        sys.stdin = old_stdin
        if old_env is None:
            os.environ.pop("SPINEMU_TRACEBACK", None)
        else:
            os.environ["SPINEMU_TRACEBACK"] = old_env
        _close_figures()
        if own:
            shutil.rmtree(workdir, ignore_errors=True)
    return findings, statuses


def _stop_timers(on: bool) -> None:
    if on:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.setitimer(signal.ITIMER_REAL, 0)


def _close_figures() -> None:
    """Free matplotlib figures a plot command left open (only if pyplot was imported)."""
    plt = sys.modules.get("matplotlib.pyplot")
    if plt is not None:
        plt.close("all")


def run_campaign(first_seed: int, cases: int, kind: Optional[str] = None, budget_s: float = 20.0,
                 progress=None) -> Campaign:
    """Run the cases ``first_seed .. first_seed + cases - 1`` and collect their findings."""
    camp = Campaign(first_seed)
    t0 = time.perf_counter()
    for seed in range(first_seed, first_seed + cases):
        case = make_case(seed, kind)
        findings, statuses = run_case(case, budget_s)
        camp.cases += 1
        camp.commands += len(statuses)
        camp.kinds[case.kind] += 1
        camp.statuses.update(statuses)
        camp.kind_statuses.update((case.kind, " ".join(argv[:2]) if argv[0] == "trace" else argv[0], status)
                                  for argv, status in zip(case.commands, statuses))
        camp.findings.extend(findings)
        if progress:
            progress(camp, case, findings)
    camp.seconds = time.perf_counter() - t0
    return camp
