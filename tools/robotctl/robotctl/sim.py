"""Port `sim:[MODEL|ELF]`: starts the virtual Mega (`vbench --pty`) on a
firmware ELF and connects to the pseudo-terminal it prints on its first line.
"""
import os
import pathlib
import shutil
import subprocess
import tempfile
import threading
from collections import deque
from typing import Deque, List, Optional

from .link import LinkError

DEFAULT_MODEL = "sprawl8"
#: The virtual sonar's echo [mm] unless told otherwise: an open room, so that
#: the robot may walk forward (with no echo at all the firmware reports a
#: sensor fault and avoidance holds forward motion back).
DEFAULT_RANGE_MM = "2000"


def parse_range(text: str) -> str:
    """`--sim-range`: millimetres >= 0 or `none` (no echo), as vbench's `range` directive."""
    t = text.strip().lower()
    if t == "none":
        return t
    try:
        if float(t) >= 0:
            return t
    except ValueError:
        pass
    raise ValueError(f"sim range must be millimetres >= 0 or none, not {text!r}")


def repo_root(start: Optional[pathlib.Path] = None) -> Optional[pathlib.Path]:
    """The Strider checkout containing `start` (default: the working
    directory), found by its lib/strider folder; None outside one."""
    p = (start or pathlib.Path.cwd()).resolve()
    for d in [p, *p.parents]:
        if (d / "lib" / "strider").is_dir() and (d / "tools" / "robotctl").is_dir():
            return d
    return None


def build_dir(explicit: Optional[str] = None) -> Optional[pathlib.Path]:
    """--build-dir, else $STRIDER_BUILD_DIR, else out/build of the checkout."""
    if explicit:
        return pathlib.Path(explicit)
    env = os.environ.get("STRIDER_BUILD_DIR")
    if env:
        return pathlib.Path(env)
    root = repo_root()
    return root / "out" / "build" if root else None


def find_vbench(explicit: Optional[str] = None, build: Optional[pathlib.Path] = None) -> Optional[str]:
    for cand in (explicit, os.environ.get("STRIDER_VBENCH")):
        if cand:
            return cand
    if build is not None:
        p = build / "tools" / "vbench" / "vbench"
        if p.is_file():
            return str(p)
    return shutil.which("vbench")


def find_elf(spec: str, explicit: Optional[str] = None, build: Optional[pathlib.Path] = None) -> Optional[str]:
    """The firmware for `sim:SPEC`: SPEC is a model name or an ELF path."""
    if explicit:
        return explicit
    if spec.endswith(".elf"):
        return spec
    if not spec and os.environ.get("STRIDER_ELF"):
        return os.environ["STRIDER_ELF"]
    model = spec or DEFAULT_MODEL
    if build is not None:
        p = build / "src" / f"strider_firmware_{model}.elf"
        if p.is_file():
            return str(p)
    return None


class VirtualMega:
    """A running `vbench --pty`; use as a context manager."""

    def __init__(self, vbench: str, elf: str, eeprom: Optional[str] = None, extra: Optional[List[str]] = None,
                 range_mm: Optional[str] = None):
        """range_mm: the sonar's echo from the start (millimetres or `none`);
        None leaves vbench's own default (no echo)."""
        self.cmd = [vbench, "--elf", elf, "--pty"]
        if eeprom:
            self.cmd += ["--eeprom", eeprom]
        self.script: Optional[str] = None
        if range_mm is not None:
            fd, self.script = tempfile.mkstemp(prefix="robotctl-", suffix=".vbench")
            with os.fdopen(fd, "w") as f:
                f.write(f"at 0 range {parse_range(range_mm)}\n")
            self.cmd += ["--script", self.script]
        self.cmd += list(extra or [])
        self.proc: Optional[subprocess.Popen] = None
        self.pty: Optional[str] = None
        self.output: Deque[str] = deque(maxlen=200)  #: vbench's own stdout/stderr lines

    def start(self, timeout: float = 15.0) -> str:
        try:
            self.proc = subprocess.Popen(self.cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                         stdin=subprocess.DEVNULL, text=True, bufsize=1)
        except OSError as e:
            raise LinkError(f"cannot start {self.cmd[0]}: {e}") from e
        first: List[str] = []
        got = threading.Event()

        def drain(stream, keep_first):
            for line in stream:
                line = line.rstrip("\n")
                if keep_first and not first:
                    first.append(line)
                    got.set()
                    continue
                self.output.append(line)
            if keep_first:
                got.set()

        threading.Thread(target=drain, args=(self.proc.stdout, True), daemon=True).start()
        threading.Thread(target=drain, args=(self.proc.stderr, False), daemon=True).start()
        if not got.wait(timeout) or not first or not first[0].strip():
            self.stop()
            raise LinkError(f"vbench printed no pty path within {timeout:g} s: {' | '.join(self.output)}")
        self.pty = first[0].strip()
        return self.pty

    def stop(self) -> None:
        if self.proc is not None and self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(5)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        if self.script is not None:
            try:
                os.unlink(self.script)
            except OSError:
                pass
            self.script = None

    def __enter__(self) -> "VirtualMega":
        self.start()
        return self

    def __exit__(self, *exc) -> None:
        self.stop()
