"""Timed scripts for `robotctl play`.

One step per line, `#` starts a comment:

    at T send TEXT     send TEXT at T seconds after the start (\\n \\r escapes;
                       a line ending is added when TEXT has none)
    at T rc BYTES      send RC-app bytes (F B L R G I H J S 0-9 q) at T, no reply
    +S send TEXT       S seconds after the previous step (also `+S rc BYTES`)
    wait S             pause S seconds after the previous step
    TEXT               a text command, sent as soon as the previous step is done

`at T send` is the strider-sim scenario syntax, so a scenario file plays
against a robot as it is; its simulator-only directives (robot, duration,
obstacle, and vbench's range/reset) are skipped.
"""
import re
from dataclasses import dataclass
from typing import List, Optional

from .protocol import unescape

SIM_ONLY = ("robot", "duration", "obstacle", "range", "reset")


class ScriptError(ValueError):
    pass


@dataclass
class Step:
    lineno: int
    kind: str                 #: 'send' (text, ends added), 'rc' (bytes), 'wait', 'skip'
    payload: str = ""
    at: Optional[float] = None     #: absolute time [s] from the start
    after: Optional[float] = None  #: delay after the previous step [s]


_TIME = r"(\d+(?:\.\d*)?|\.\d+)"


def _number(text: str, lineno: int) -> float:
    if not re.fullmatch(_TIME, text):
        raise ScriptError(f"line {lineno}: '{text}' is not a time in seconds")
    return float(text)


def _action(words: str, lineno: int, at=None, after=None) -> Step:
    verb, _, rest = words.partition(" ")
    rest = rest.strip()
    if verb == "send":
        if not rest:
            raise ScriptError(f"line {lineno}: send needs a text")
        text = unescape(rest)
        if not text.endswith(("\n", "\r")):
            text += "\n"
        return Step(lineno, "send", text, at=at, after=after)
    if verb == "rc":
        if not rest:
            raise ScriptError(f"line {lineno}: rc needs bytes")
        return Step(lineno, "rc", rest.replace(" ", ""), at=at, after=after)
    if verb in SIM_ONLY:
        return Step(lineno, "skip", words, at=at, after=after)
    raise ScriptError(f"line {lineno}: expected 'send TEXT' or 'rc BYTES' after the time, got '{verb}'")


def parse_script(text: str) -> List[Step]:
    steps: List[Step] = []
    last_at = 0.0
    for lineno, raw in enumerate(text.splitlines(), 1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        m = re.fullmatch(r"at\s+(\S+)\s+(.+)", line)
        if m:
            t = _number(m.group(1), lineno)
            if t < last_at:
                raise ScriptError(f"line {lineno}: time {t:g} s is before the previous step's {last_at:g} s")
            last_at = t
            steps.append(_action(m.group(2), lineno, at=t))
            continue
        m = re.fullmatch(r"\+(\S+)\s+(.+)", line)
        if m:
            steps.append(_action(m.group(2), lineno, after=_number(m.group(1), lineno)))
            continue
        m = re.fullmatch(r"wait\s+(\S+)", line)
        if m:
            steps.append(Step(lineno, "wait", after=_number(m.group(1), lineno)))
            continue
        first = line.split()[0]
        if first in SIM_ONLY:
            steps.append(Step(lineno, "skip", line))
            continue
        steps.append(Step(lineno, "send", line + "\n"))
    return steps


@dataclass
class PlayResult:
    sent: int = 0        #: text lines sent
    errors: int = 0      #: err replies
    timeouts: int = 0    #: lines without a reply in time


def play(link, steps: List[Step], log, timeout: float = 2.0) -> PlayResult:
    """Runs `steps` on `link` (a robotctl Link). Waits are spent polling the
    link, so notices show up while nothing is sent. `log(text)` gets one
    line per action and per reply."""
    from .link import ReplyTimeout  # late import: no cycle with link at load

    res = PlayResult()
    start = link.clock()
    prev_done = start

    def elapsed():
        return link.clock() - start

    def wait_until(t_abs):
        while True:
            left = t_abs - link.clock()
            if left <= 0:
                return
            link.poll(left)

    for step in steps:
        if step.at is not None:
            wait_until(start + step.at)
        elif step.after is not None:
            wait_until(prev_done + step.after)
        if step.kind == "wait":
            prev_done = link.clock()
            continue
        if step.kind == "skip":
            log(f"{elapsed():7.3f}   (skipped, simulator only: {step.payload})")
            prev_done = link.clock()
            continue
        if step.kind == "rc":
            link.write_rc(step.payload)
            log(f"{elapsed():7.3f} > rc {step.payload}")
            prev_done = link.clock()
            continue
        shown = step.payload.replace("\r", "\\r").replace("\n", "\\n")
        if shown.endswith("\\n") and shown.count("\\") == 1:
            shown = shown[:-2]
        log(f"{elapsed():7.3f} > {shown}")
        for req in link.write_raw(step.payload):
            res.sent += 1
            try:
                r = link.wait_reply(req, timeout)
                log(f"{elapsed():7.3f} < {r.line}")
                res.errors += 0 if r.ok else 1
            except ReplyTimeout as e:
                log(f"{elapsed():7.3f} ! {e}")
                res.timeouts += 1
        prev_done = link.clock()
    return res
