"""The robot's line protocol (docs/protocol.md): classifying received lines,
parsing replies and the status line, and what may be sent.

Every text line sent gets exactly one reply, `ok ...` or `err <code> <reason>`;
lines starting with `info` are asynchronous notices and never replies. RC
characters (the phone app's buttons) get no reply.
"""
import binascii
import re
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple, Union

#: RC motion buttons of the phone app (docs/protocol.md, "RC app buttons").
RC_MOTION = "FBLRGIHJS"
#: RC speed slider: 0-9 are 0-90 %, q is 100 %.
RC_SPEED = "0123456789q"
#: Everything the robot takes as an RC byte between lines.
RC_BYTES = RC_MOTION + RC_SPEED

#: Longest text line the robot accepts, without its ending [bytes].
MAX_LINE_BYTES = 63
#: What a checked line adds to its text: `$` before, `*hhhh` after.
CHECK_BYTES = 6

#: Error codes the robot guarantees (docs/protocol.md, "Error codes").
ERROR_CODES = {
    1: "unknown command",
    2: "bad argument",
    3: "missing argument",
    4: "too many arguments",
    5: "out of range",
    6: "line too long",
    7: "bad byte",
    8: "incomplete line",
    9: "bad checksum",
    10: "bytes lost",
    11: "checksum required",
    20: "cal start first",
    21: "calibrating",
    22: "store failed",
    23: "unknown gait",
    24: "pose refused",  # or "height refused"
    25: "step_height out of range",  # or step_length, cycle, duty; "swing not under the model's own swing"
    30: "model does not fit the firmware",
    31: "servo fault",
    32: "battery critical",
    33: "fallen",
    34: "no imu",
    35: "not standing still",
    36: "not level",
    37: "servos do not fit the firmware",
    38: "no gait defaults for the model",
}

Value = Union[int, float, str]


def crc16(text: str) -> int:
    """CRC-16/CCITT-FALSE of a line's text, the robot's line check
    (docs/protocol.md, "Checked lines"): crc16("123456789") == 0x29B1."""
    return binascii.crc_hqx(text.encode("latin-1"), 0xFFFF)


def checked_line(text: str) -> str:
    """`$text*hhhh`: a text line in its checked form."""
    return f"${text}*{crc16(text):04x}"


_CHECK = re.compile(r"^(.*)\*([0-9A-Fa-f]{4})$")


def split_check(line: str) -> Tuple[str, Optional[bool]]:
    """A received line without its `*hhhh`, and whether that check holds:
    (line, None) for a line without one."""
    m = _CHECK.match(line)
    if not m:
        return line, None
    return m.group(1), crc16(m.group(1)) == int(m.group(2), 16)


def convert(text: str) -> Value:
    """A status value as int, float or the text itself."""
    try:
        return int(text)
    except ValueError:
        pass
    try:
        return float(text)
    except ValueError:
        return text


def parse_fields(words: List[str]) -> Dict[str, Value]:
    """`key=value` words into a dict; other words are left out."""
    out: Dict[str, Value] = {}
    for w in words:
        if "=" in w:
            k, v = w.split("=", 1)
            out[k] = convert(v)
    return out


@dataclass
class Reply:
    """One `ok ...` or `err <code> <reason>: <valid values>` line."""
    line: str
    ok: bool
    words: List[str] = field(default_factory=list)   #: words after ok/err
    code: Optional[int] = None                        #: error code (err only)
    reason: str = ""                                  #: error reason (err only)
    valid: str = ""                                   #: what is valid, after the reason's colon (err only)
    fields: Dict[str, Value] = field(default_factory=dict)  #: key=value words
    checked: bool = False                             #: it came with a check that held

    @property
    def what(self) -> str:
        """The first word after `ok` (e.g. `move`, `status`), or ''."""
        return self.words[0] if self.words else ""


def kind_of(line: str) -> str:
    """'ok', 'err', 'info' or 'other' (boot noise, echoes)."""
    first = line.split(" ", 1)[0]
    if first in ("ok", "err", "info"):
        return first
    return "other"


def parse_reply(line: str) -> Optional[Reply]:
    """The reply in `line`, or None when it is not an ok/err line."""
    words = line.split()
    if not words or words[0] not in ("ok", "err"):
        return None
    if words[0] == "ok":
        return Reply(line=line, ok=True, words=words[1:], fields=parse_fields(words[1:]))
    code = None
    reason = " ".join(words[1:])
    if len(words) > 1:
        try:
            code = int(words[1])
            reason = " ".join(words[2:])
        except ValueError:
            pass
    reason, _, valid = reason.partition(": ")
    return Reply(line=line, ok=False, words=words[1:], code=code, reason=reason, valid=valid)


def parse_status(reply: Reply) -> Dict[str, Value]:
    """The fields of an `ok status ...` reply; ValueError for anything else."""
    if not reply.ok or reply.what != "status":
        raise ValueError(f"not a status reply: {reply.line!r}")
    return dict(reply.fields)


def status_summary(st: Dict[str, Value]) -> str:
    """One short line for a status dict, for the drive screen and `status`."""
    parts = [f"mode={st.get('mode', '?')}", f"speed={st.get('speed', '?')}%"]
    if "vx" in st or "vy" in st or "wz" in st:
        parts.append(f"v=({st.get('vx', '?')}, {st.get('vy', '?')}) mm/s wz={st.get('wz', '?')} deg/s")
    parts.append(f"avoid={st.get('avoid', '?')}")
    sonar = f"sonar={st.get('sonar', '?')}"
    if "dist_mm" in st:
        sonar += f" {st['dist_mm']} mm"
    parts.append(sonar)
    for k in ("deadman_ms", "eeprom"):
        if k in st:
            parts.append(f"{k}={st[k]}")
    return "  ".join(parts)


def check_line(text: str, checked: bool = False) -> Optional[str]:
    """Why the robot would refuse `text` as a line (sent checked: in its
    checked form), or None. Robotctl sends it anyway (the robot's own answer
    is the truth); this is for warnings."""
    try:
        raw = text.encode("ascii")
    except UnicodeEncodeError:
        return "non-ASCII characters (err 7 bad byte)"
    limit = MAX_LINE_BYTES - (CHECK_BYTES if checked else 0)
    if len(raw) > limit:
        return f"longer than {limit} bytes{' with its check' if checked else ''} (err 6 line too long)"
    if any(b < 0x20 and b != 0x09 or b > 0x7E for b in raw):
        return "control characters (err 7 bad byte)"
    if raw[:1].isupper() and len(raw.strip()) > 1:
        return "starts with an uppercase letter: read as an RC button, then the rest"
    return None


def unescape(text: str) -> str:
    r"""Scenario-style escapes: \n \r \t \\ (as in strider-sim's `send`)."""
    out = []
    i = 0
    while i < len(text):
        c = text[i]
        if c == "\\" and i + 1 < len(text):
            n = text[i + 1]
            mapped = {"n": "\n", "r": "\r", "t": "\t", "\\": "\\"}.get(n)
            if mapped is not None:
                out.append(mapped)
                i += 2
                continue
        out.append(c)
        i += 1
    return "".join(out)


def replies_expected(payload: str) -> int:
    """How many replies a raw payload earns: one per non-empty line that is
    ended (CR, LF or CR LF); RC bytes outside lines earn none."""
    count = 0
    pending = False
    prev_cr = False
    for c in payload:
        if c in "\r\n":
            if c == "\n" and prev_cr:
                prev_cr = False
                continue
            if pending:
                count += 1
            pending = False
            prev_cr = c == "\r"
            continue
        prev_cr = False
        pending = True
    return count


#: The word after `ok` that each command's success reply starts with.
OK_WORD = {
    "walk": "move", "strafe": "move", "turn": "move", "vel": "move", "velocity": "move",
    "stop": "stop", "relax": "relax", "speed": "speed", "gait": "gait", "pose": "pose", "height": "height",
    "avoid": "avoid", "level": "level", "deadman": "deadman", "baud": "baud", "cal": "cal", "save": "saved",
    "status": "status", "help": "help", "w": "light", "u": "light", "v": "light", "x": "light",
}


def plausible(line_sent: str, reply: Reply) -> bool:
    """Whether `reply` can answer `line_sent`: any err can, an ok only when
    its first word fits the command (unknown commands: anything fits)."""
    if not reply.ok:
        return True
    words = line_sent.split()
    if not words:
        return True
    cmd = words[0]
    if len(cmd) == 1 and cmd in RC_BYTES and len(words) == 1:
        return reply.what == "rc"
    want = OK_WORD.get(cmd)
    return want is None or reply.what == want
