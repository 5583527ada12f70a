"""Running the reference tools on a generated program (OpenSpin, spinsim) and spinemu's own compiler and chip.

The reference tools are black boxes found at run time (``--openspin``,
``--spinsim`` or the ``SPINEMU_OPENSPIN`` / ``SPINEMU_SPINSIM`` variables);
tests never need them: what they said is recorded under ``tests/data/fuzz``.
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile

from spinemu.diagnostics import SpinError

OPENSPIN = os.environ.get("SPINEMU_OPENSPIN", "/opt/oracles/OpenSpin/build/openspin")
SPINSIM = os.environ.get("SPINEMU_SPINSIM", "/opt/oracles/spinsim/build/spinsim")


def available(path: str) -> bool:
    return bool(path) and os.path.isfile(path) and os.access(path, os.X_OK)


def openspin_compile(program, exe: str = OPENSPIN):
    """``(image, None)`` from OpenSpin, or ``(None, its message)`` when it rejects the program."""
    with tempfile.TemporaryDirectory(prefix="fuzz-") as tmp:
        top = program.write(tmp)
        out = os.path.join(tmp, "out.binary")
        r = subprocess.run([exe, "-q", "-b", top, "-o", out], capture_output=True, text=True,
                           errors="replace", timeout=60)
        if r.returncode == 0 and os.path.exists(out):
            with open(out, "rb") as fh:
                return fh.read(), None
        if r.returncode < 0:
            return None, f"crashed (signal {-r.returncode})"
        return None, (r.stdout + r.stderr).strip().replace(tmp + os.sep, "")


def spinemu_compile(program):
    """``(image, None)`` from spinemu's compiler, or ``(None, its rendered errors)``."""
    from spinemu.compiler import compile_file
    with tempfile.TemporaryDirectory(prefix="fuzz-") as tmp:
        top = program.write(tmp)
        try:
            return compile_file(top).binary, None
        except SpinError as exc:
            return None, str(exc).replace(tmp + os.sep, "")


def spinsim_hub(binary: bytes, exe: str = SPINSIM, timeout: float = 120) -> bytes:
    """Hub RAM (32 KB) after ``binary`` ran on spinsim ``-p`` until every cog stopped."""
    with tempfile.TemporaryDirectory(prefix="fuzz-") as tmp:
        path = os.path.join(tmp, "prog.binary")
        with open(path, "wb") as fh:
            fh.write(binary)
        r = subprocess.run([exe, "-p", "-d", path], input="run\ndumph 0\nexit\n", capture_output=True,
                           text=True, timeout=timeout, cwd=tmp)
    mem = bytearray(0x8000)
    for a, v in re.findall(r"([0-9a-f]{8}) ([0-9a-f]{8})", r.stdout):
        a = int(a, 16)
        if a < 0x8000:
            mem[a:a + 4] = int(v, 16).to_bytes(4, "little")
    return bytes(mem)


def spinemu_run(binary: bytes, max_cycles: int = 200_000_000):
    """spinemu's chip (bytecode engine, spinsim timing) run to its end: the ChipResult."""
    from spinemu.chip import Chip
    return Chip(binary, compat="spinsim").run(max_cycles=max_cycles)


def which(name: str) -> str | None:
    return shutil.which(name)
