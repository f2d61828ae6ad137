"""Keyboard driving (`robotctl drive`): keys become the phone app's RC bytes.

A terminal reports key presses but not releases, so there are two modes:
- latch (default): a motion key keeps the robot moving until space (stop) or
  another motion key; robotctl repeats the motion byte every `repeat_s` so the
  robot's deadman (which stops it when the link goes quiet) stays satisfied
  while robotctl runs, and fires if robotctl dies or the link drops.
- hold: like the phone app, moving only while the key is held: the
  terminal's key repeat keeps it going, and `release_s` without a motion key
  sends S (stop).

The logic (DriveState) is separate from the curses screen so it can be
tested with a fake link and clock.
"""
import time
from dataclasses import dataclass, field
from typing import Callable, Deque, Dict, List, Optional
from collections import deque

from .protocol import RC_SPEED, parse_status, status_summary

#: Keys -> RC motion bytes. Named keys come from the screen layer.
MOTION_KEYS: Dict[str, str] = {
    "UP": "F", "w": "F",
    "DOWN": "B", "s": "B",
    "LEFT": "L", "a": "L",
    "RIGHT": "R", "d": "R",
    "z": "G",   # turn anticlockwise
    "c": "I",   # turn clockwise
    "[": "H",   # back-left
    "]": "J",   # back-right
}
# The app's own letters, typed with shift, work too.
MOTION_KEYS.update({c: c for c in "FBLRGIHJ"})

MOTION_NAMES = {
    "F": "forward", "B": "backward", "L": "sideways left", "R": "sideways right",
    "G": "turn anticlockwise", "I": "turn clockwise", "H": "back-left", "J": "back-right", "S": "stop",
}

STOP_KEYS = (" ", "S", "x")
QUIT_KEYS = ("ESC", "Q", "CTRL_C")
LINE_KEYS = ("t", "ENTER")

#: Tune keys: a step of one live gait parameter of the gait walked now
#: (`set NAME VALUE`, docs/protocol.md), from the values of the last `get`.
TUNE_KEYS: Dict[str, tuple] = {
    "u": ("step_height", +1.0), "j": ("step_height", -1.0),
    "i": ("step_length", +5.0), "k": ("step_length", -5.0),
    "l": ("cycle", +0.05), "o": ("cycle", -0.05),
    "y": ("duty", +0.01), "h": ("duty", -0.01),
}
SWING_KEY = "n"   # the next swing shape
SAVE_KEY = "p"    # save: the gait's parameters stay over a power cycle
SWINGS = ("rectangle", "semicircle", "ellipse", "cycloid", "parabola", "bezier")
TUNE_FIELDS = ("gait", "step_height", "step_length", "cycle", "duty", "swing")

HELP = ("arrows/WASD move  z/c turn  [ ] back-left/right  space stop  0-9 q speed  "
        "t or Enter: type a command  Esc/Q quit")
TUNE_HELP = "tune: u/j step height  i/k step length  o/l cycle  y/h duty  n swing  p save"


def speed_percent(ch: str) -> int:
    return 100 if ch == "q" else int(ch) * 10


@dataclass
class DriveState:
    link: object                        #: a robotctl Link
    latch: bool = True
    repeat_s: float = 0.25              #: motion byte repeat period (latch) [s]
    release_s: float = 0.6              #: hold mode: stop after this long without a key [s]
    status_period_s: float = 1.0        #: status refresh period; 0 = never [s]
    motion: str = "S"                   #: current RC motion byte
    speed_pct: Optional[int] = None
    last_sent: str = ""
    last_reply: str = ""
    status: Dict[str, object] = field(default_factory=dict)
    status_line: str = "status: waiting"
    notices: Deque[str] = field(default_factory=lambda: deque(maxlen=5))
    quit: bool = False
    _last_motion_write: float = -1e9
    _last_motion_key: float = -1e9
    _status_req: object = None
    _status_sent: float = -1e9
    _user_reqs: List[object] = field(default_factory=list)
    tune: Dict[str, str] = field(default_factory=dict)  #: the last `get`: the gait's live parameters
    _tune_reqs: List[tuple] = field(default_factory=list)  # (kind "get"/"set", request)
    _swing_tried: Optional[str] = None

    @property
    def clock(self) -> Callable[[], float]:
        return self.link.clock

    def key(self, k: str) -> None:
        """One key press (a character or UP/DOWN/LEFT/RIGHT/ESC/ENTER/CTRL_C)."""
        now = self.clock()
        if k in QUIT_KEYS:
            self.stop()
            self.quit = True
        elif k in STOP_KEYS:
            self.stop()
        elif k in MOTION_KEYS:
            self._last_motion_key = now
            self._move(MOTION_KEYS[k], now)
        elif k in RC_SPEED:
            self.speed_pct = speed_percent(k)
            self.link.write_rc(k)
            self.last_sent = f"{k} (speed {self.speed_pct} %)"
        elif k in TUNE_KEYS or k in (SWING_KEY, SAVE_KEY):
            self._tune_key(k)

    def _tune_key(self, k: str) -> None:
        """A tune key: `set` of the parameter a step from what `get` showed
        (the robot refuses a value it cannot take, with its range, shown as
        the reply), or `save`."""
        if k == SAVE_KEY:
            line = "save"
        elif not self.tune:  # nothing to step from yet
            self._ask_tune()
            return
        elif k == SWING_KEY:
            now = self._swing_tried or self.tune.get("swing", SWINGS[0])
            nxt = SWINGS[(SWINGS.index(now) + 1) % len(SWINGS)] if now in SWINGS else SWINGS[0]
            self._swing_tried = nxt
            line = f"set swing {nxt}"
        else:
            name, step = TUNE_KEYS[k]
            try:
                value = float(self.tune[name]) + step
            except (KeyError, ValueError):
                self._ask_tune()
                return
            line = f"set {name} {max(value, 0.0):.2f}"
        self._tune_reqs.append(("set", self.link.write_line(line)))
        self.last_sent = line

    def _ask_tune(self) -> None:
        if not any(kind == "get" for kind, _ in self._tune_reqs):
            self._tune_reqs.append(("get", self.link.write_line("get")))

    @property
    def tune_line(self) -> str:
        if not self.tune:
            return "tune:    (press a tune key)"
        return "tune:    " + "  ".join(f"{k}={self.tune[k]}" for k in TUNE_FIELDS if k in self.tune)

    def _move(self, byte: str, now: float) -> None:
        self.motion = byte
        self.link.write_rc(byte)
        self._last_motion_write = now
        self.last_sent = f"{byte} ({MOTION_NAMES[byte]})"

    def stop(self) -> None:
        self.motion = "S"
        self.link.write_rc("S")
        self.last_sent = "S (stop)"

    def send_line(self, text: str) -> None:
        """A typed text command; its reply shows as the last reply."""
        if text.strip():
            self._user_reqs.append(self.link.write_line(text))
            self.last_sent = text

    def tick(self) -> None:
        """Call often (every ~50 ms): repeats, releases, status, replies."""
        now = self.clock()
        if self.motion != "S":
            if not self.latch and now - self._last_motion_key >= self.release_s:
                self.stop()
            elif now - self._last_motion_write >= self.repeat_s:
                self.link.write_rc(self.motion)
                self._last_motion_write = now
        if self.status_period_s > 0 and self._status_req is None and now - self._status_sent >= self.status_period_s:
            self._status_req = self.link.write_line("status")
            self._status_sent = now
        self.link.poll(0)
        self._collect(now)

    def _collect(self, now: float) -> None:
        for ev in self.link.notices:
            self.notices.append(ev.line)
        self.link.notices.clear()
        req = self._status_req
        if req is not None and req.reply is not None:
            try:
                self.status = parse_status(req.reply)
                self.status_line = "status: " + status_summary(self.status)
            except ValueError:
                self.status_line = "status: " + req.reply.line
            self._status_req = None
        elif req is not None and now - req.sent_at > max(3.0, 3 * self.status_period_s):
            req.abandoned = True  # its late reply will be dropped by the link
            self._status_req = None
            self.status_line = "status: no reply (link down?)"
        for r in list(self._user_reqs):
            if r.reply is not None:
                self.last_reply = r.reply.line
                self._user_reqs.remove(r)
                if self.tune:  # a typed `gait ...` or `set ...` changes what the tune line shows
                    self._swing_tried = None
                    self._ask_tune()
        for kind, r in list(self._tune_reqs):
            if r.reply is None:
                continue
            self._tune_reqs.remove((kind, r))
            if kind == "get":
                if r.reply.ok:
                    self.tune = {k: v for k, v in (kv.split("=", 1) for kv in r.reply.line.split()[2:] if "=" in kv)}
            else:  # a set or save: its reply, then the values as they are now
                self.last_reply = r.reply.line
                if r.reply.ok:
                    self._swing_tried = None
                self._ask_tune()


# -- curses screen -------------------------------------------------------------

def run_curses(drive: DriveState, title: str) -> None:
    import curses

    named = {curses.KEY_UP: "UP", curses.KEY_DOWN: "DOWN", curses.KEY_LEFT: "LEFT", curses.KEY_RIGHT: "RIGHT",
             27: "ESC", 3: "CTRL_C", 10: "ENTER", 13: "ENTER", curses.KEY_ENTER: "ENTER"}

    def main(scr):
        curses.raw()  # Ctrl-C arrives as a key, so quitting always sends S first
        curses.curs_set(0)
        scr.nodelay(True)
        scr.keypad(True)
        typing: Optional[str] = None
        while not drive.quit:
            try:
                k = scr.getch()
            except KeyboardInterrupt:
                k = 3
            while k != -1:
                name = named.get(k, chr(k) if 0 <= k < 256 else "")
                if typing is not None:
                    if name == "ENTER":
                        drive.send_line(typing)
                        typing = None
                    elif name in ("ESC", "CTRL_C"):
                        typing = None
                    elif k in (curses.KEY_BACKSPACE, 127, 8):
                        typing = typing[:-1]
                    elif 32 <= k < 127:
                        typing += chr(k)
                elif name in LINE_KEYS:
                    typing = ""
                else:
                    drive.key(name)
                k = scr.getch()
            drive.tick()
            draw(scr, typing)
            time.sleep(0.03)

    def draw(scr, typing):
        scr.erase()
        h, w = scr.getmaxyx()
        rows = [title, HELP, TUNE_HELP, "",
                f"mode:    {'latch' if drive.latch else 'hold'}   motion: {drive.motion} "
                f"({MOTION_NAMES[drive.motion]})   speed: "
                f"{drive.speed_pct if drive.speed_pct is not None else '?'} %",
                f"sent:    {drive.last_sent}",
                f"reply:   {drive.last_reply}",
                drive.status_line, drive.tune_line, "", "notices:"] + [f"  {n}" for n in drive.notices]
        if typing is not None:
            rows += ["", f"command> {typing}_"]
        for i, row in enumerate(rows[: h - 1]):
            scr.addnstr(i, 0, row, w - 1)
        scr.refresh()

    try:
        curses.wrapper(main)
    finally:
        drive.stop()
