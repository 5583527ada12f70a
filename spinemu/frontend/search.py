"""Where the files a program names are found: OBJ objects and DAT ``file`` data.

A name is looked up, in this order, in

1. the folder of the file that names it;
2. the folders given with ``-L`` / ``include_dirs`` (OpenSpin's ``-L``);
3. the folders in the ``SPINEMU_PATH`` environment variable, separated as in
   ``PATH`` on the platform (``:`` on Linux and macOS, ``;`` on Windows);
4. the Spin library folders of installed Propeller tools, where they exist
   (:func:`standard_library_folders`): the Propeller Tool's ``Library``,
   PropellerIDE's ``library``, SimpleIDE's (PropGCC's) ``spin`` folder.

A name that matches no file exactly in any of them is then looked up without
regard to letter case, folder by folder, as the Propeller Tool finds it on
Windows (``tv_text`` for ``TV_Text.spin``): a single match is used with a
warning; several files differing only in case in one folder are an error
naming them.  When nothing is found, the message lists every folder looked in
and, for one of the Propeller Tool's own library objects
(:data:`STANDARD_OBJECTS`), says where that library comes from.
"""
from __future__ import annotations

import os
import sys
from dataclasses import dataclass, field
from typing import Optional

from .. import messages as msg

__all__ = ["SearchPath", "Folder", "Found", "AmbiguousName", "ENV_VAR", "STANDARD_OBJECTS",
           "standard_library_folders", "standard_object"]

ENV_VAR = "SPINEMU_PATH"

#: the objects in the Propeller Tool's Library folder (v1.3; Servo32v9 from later versions), lower-case
#: name -> spelling: programs name them without shipping them
STANDARD_OBJECTS = {n.lower(): n for n in (
    "4x4 Keypad Reader", "AD8803", "ADC", "COILREAD", "CTR", "Clock", "Debug_Lcd", "Float32", "Float32A",
    "Float32Full", "FloatMath", "FloatString", "FullDuplexSerial", "Graphics", "H48C Tri-Axis Accelerometer",
    "HM55B Compass Module Asm", "Inductor", "Keyboard", "MCP3208", "MXD2125 Simple", "MXD2125",
    "Memsic2125_v1.2", "Monitor", "Mouse", "Numbers", "Parallax Serial Terminal", "Ping", "PropellerLoader",
    "PropellerRTC_Emulator", "Quadrature Encoder", "RCTIME", "RealRandom", "SPI_Asm", "SPI_Spin",
    "Serial_Lcd", "Servo32_Ramp_v2", "Servo32v7", "Servo32v9", "SimpleDebug", "Simple_Numbers",
    "Simple_Serial", "Stack Length", "StereoSpatializer", "Synth", "TV", "TV_Terminal", "TV_Text", "VGA",
    "VGA_512x384_Bitmap", "VGA_HiRes_Text", "VGA_Text", "VocalTract", "tsl230",
    "vga_1280x1024_tile_driver_with_cursor", "vga_1600x1200_tile_driver_with_cursor",
)}


@dataclass(frozen=True)
class Folder:
    """A folder to look in, and why it is on the list (for messages)."""

    path: str
    why: str


@dataclass(frozen=True)
class Found:
    """A file found for a name; ``warning`` is set when its letter case differs from the name's."""

    path: str
    warning: Optional[str] = None


class AmbiguousName(Exception):
    """Several files in one folder match a name when letter case is ignored."""

    def __init__(self, name: str, folder: str, candidates: list):
        super().__init__(name)
        self.name = name
        self.folder = folder
        self.candidates = candidates


def _program_files(environ) -> list:
    out = []
    for var in ("ProgramFiles", "ProgramFiles(x86)", "ProgramW6432"):
        value = environ.get(var)
        if value and value not in out:
            out.append(value)
    for default in (r"C:\Program Files", r"C:\Program Files (x86)"):
        if default not in out:
            out.append(default)
    return out


def _candidate_library_folders(platform: str, environ) -> list:
    """``(folder, tool)`` where the tools' installers put their Spin library, existing or not."""
    if platform.startswith("win"):
        bases = _program_files(environ)
        out = []
        import glob

        for base in bases:     # "Propeller Tool v1.3.2", "Propeller Tool" (2.x): newest name first
            tools = glob.glob(os.path.join(glob.escape(os.path.join(base, "Parallax Inc")), "Propeller Tool*"))
            out += [(os.path.join(t, "Library"), "the Propeller Tool") for t in sorted(tools, reverse=True)]
        out += [(os.path.join(b, "PropellerIDE", "library"), "PropellerIDE") for b in bases]
        out += [(os.path.join(b, "SimpleIDE", "propeller-gcc", "spin"), "SimpleIDE") for b in bases]
        return out
    if platform == "darwin":
        app = "/Applications/PropellerIDE.app/Contents/Resources/library"
        return [(app, "PropellerIDE"), (os.path.join(app, "library"), "PropellerIDE"),
                ("/opt/parallax/spin", "SimpleIDE")]
    return [("/usr/share/propelleride/library", "PropellerIDE"),
            ("/usr/local/share/propelleride/library", "PropellerIDE"),
            ("/opt/parallax/spin", "SimpleIDE")]


def _library_decisions(platform: str, environ) -> list:
    """The folders whose existence or files decide :func:`standard_library_folders`."""
    out = [path for path, _tool in _candidate_library_folders(platform, environ)]
    if platform.startswith("win"):
        out += [os.path.join(base, "Parallax Inc") for base in _program_files(environ)]
    return out


def standard_library_folders(platform: Optional[str] = None, environ=None) -> list:
    """The installed tools' Spin library folders that exist on this machine, as :class:`Folder`.

    Args:
        platform: ``sys.platform`` by default (``"win32"``, ``"darwin"``, ``"linux"``).
        environ: ``os.environ`` by default (Windows: ``ProgramFiles``...).
    """
    platform = sys.platform if platform is None else platform
    environ = os.environ if environ is None else environ
    seen, out = set(), []
    for path, tool in _candidate_library_folders(platform, environ):
        if os.path.isdir(path) and os.path.realpath(path) not in seen:
            seen.add(os.path.realpath(path))
            out.append(Folder(path, f"{tool}'s library"))
    return out


def standard_object(name: str) -> Optional[str]:
    """The Propeller Tool library object ``name`` stands for (any case, ``.spin`` or not), or None."""
    stem = name[:-5] if name.lower().endswith(".spin") else name
    return STANDARD_OBJECTS.get(stem.lower())


@dataclass
class SearchPath:
    """The folders names are looked up in (besides the naming file's own) and the warnings given.

    Args:
        include_dirs: ``-L`` folders, searched first.
        environ: where ``SPINEMU_PATH`` is read (``os.environ`` by default); ``{}`` reads nothing.
        standard: also search the installed tools' library folders.
        platform: for :func:`standard_library_folders` (tests).

    >>> sp = SearchPath(["lib"], environ={"SPINEMU_PATH": os.pathsep.join(["a", "b"])}, standard=False)
    >>> [(f.path, f.why) for f in sp.folders("src")]
    [('src', "the source's folder"), ('lib', '-L'), ('a', 'SPINEMU_PATH'), ('b', 'SPINEMU_PATH')]
    """

    include_dirs: list = field(default_factory=list)
    environ: Optional[dict] = None
    standard: bool = True
    platform: Optional[str] = None
    #: "warning" Diagnostics-to-be: ``(message, node)`` filled in by the callers
    warnings: list = field(default_factory=list)

    def __post_init__(self):
        environ = os.environ if self.environ is None else self.environ
        self._extra = [Folder(d, "-L") for d in self.include_dirs]
        for d in (environ.get(ENV_VAR) or "").split(os.pathsep):
            if d.strip():
                self._extra.append(Folder(os.path.expanduser(d.strip()), ENV_VAR))
        #: what the lookups depended on (spinemu.progcache checks it before reusing a compiled
        #: program): the folders whose files decided a lookup, existing or not, and the files
        #: whose contents went into the program (the loader and the DAT ``file`` reader add these)
        self.dirs: set = set()
        self.files: dict = {}       # path -> (size, CRC-32) of the bytes used, None: of the file as it is
        if self.standard:
            self._extra += standard_library_folders(self.platform, environ)
            platform = sys.platform if self.platform is None else self.platform
            self.dirs.update(_library_decisions(platform, environ))
        self._listing: dict = {}

    def folders(self, from_dir: str) -> list:
        """Every folder looked in for a name used in a file of ``from_dir``, in order."""
        return [Folder(from_dir, "the source's folder")] + self._extra

    def describe(self, from_dir: str) -> str:
        """The folders, for a "looked in" message."""
        return "; ".join(f"{f.path} ({f.why})" for f in self.folders(from_dir))

    def _entries(self, folder: str) -> list:
        if folder not in self._listing:
            try:
                self._listing[folder] = sorted(os.listdir(folder))
            except OSError:
                self._listing[folder] = []
        return self._listing[folder]

    def find(self, name: str, from_dir: str) -> Optional[Found]:
        """The file ``name`` stands for, or None: folder by folder, an exact match, then one in any letter case.

        A folder's own file in another case comes before an exact match in a later folder,
        as on Windows, where the Propeller Tool opens the project's copy whatever its case.

        Raises:
            AmbiguousName: no exact match in a folder, and several of its files match in another case.
        """
        head, base = os.path.split(name)
        low = base.lower()
        for f in self.folders(from_dir):
            self.dirs.add(os.path.join(f.path, head) if head else f.path)
            cand = os.path.join(f.path, name)
            if os.path.isfile(cand):
                return Found(cand)
            where = os.path.join(f.path, head) if head else f.path
            matches = [e for e in self._entries(where) if e.lower() == low
                       and os.path.isfile(os.path.join(where, e))]
            if len(matches) > 1:
                raise AmbiguousName(name, where, matches)
            if matches:
                path = os.path.join(where, matches[0])
                return Found(path, msg.NAME_IN_OTHER_CASE.format(name=name, actual=matches[0], folder=where))
        return None
