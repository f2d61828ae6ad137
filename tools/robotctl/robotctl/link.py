"""The serial link to the robot: writes lines and RC bytes, reads lines, and
pairs replies with the lines that earned them.

Replies come in the order of the lines sent, so the link keeps a queue of
lines still waiting for one. A reply that arrives after its command timed out
(the HC-05 buffers, a busy robot answers late) is matched to that stale entry
and dropped, so it is never taken for the answer to a later command.

Text lines go out as checked lines (`$text*hhhh`, docs/protocol.md) unless
the link is plain: the robot then runs only a line that arrived whole, and
its reply carries a check too. A received line whose check fails is damaged:
it is reported (kind 'damaged') and answers nothing.
"""
import re
import time
from collections import deque
from dataclasses import dataclass, field
from typing import Callable, Deque, List, Optional

import serial

from .protocol import RC_BYTES, Reply, checked_line, kind_of, parse_reply, plausible, split_check

#: Ports that reset an Arduino when opened (DTR): wait for its boot lines.
RESETTING_PORT = re.compile(r"^/dev/(ttyACM|ttyUSB|cu\.usbmodem|cu\.usbserial)")


class LinkError(Exception):
    """The port could not be opened or the link broke."""


class ReplyTimeout(LinkError):
    """No reply to a line within the timeout."""


@dataclass
class Pending:
    """A text line waiting for its reply."""
    text: str
    sent_at: float
    reply: Optional[Reply] = None
    abandoned: bool = False  #: its caller gave up waiting


@dataclass
class Event:
    """A line received: kind is 'ok', 'err', 'info', 'other', or 'damaged'
    (its check failed); line is without its check."""
    time: float
    kind: str
    line: str
    checked: Optional[bool] = None      #: None: it had no check; else whether it held
    reply: Optional[Reply] = None
    request: Optional[Pending] = None  #: the line this reply answers, if known
    late: bool = False                  #: reply to an abandoned request


@dataclass
class Link:
    """A line-oriented connection to the robot over any pyserial port."""
    port: "serial.SerialBase"
    clock: Callable[[], float] = time.monotonic
    #: Called for every line received (also inside command()).
    on_event: Optional[Callable[[Event], None]] = None
    #: Line ending written after a text line.
    eol: bytes = b"\n"
    #: Text lines as checked lines (`$text*hhhh`); False: plain, as a phone app sends.
    checked: bool = True
    #: Abandoned requests older than this are forgotten [s]: a reply that
    #: never comes must not shift every later pairing forever.
    forget_after_s: float = 30.0
    notices: List[Event] = field(default_factory=list)
    _buf: bytearray = field(default_factory=bytearray)
    _skip_lf: bool = False
    _queue: Deque[Pending] = field(default_factory=deque)

    # -- writing ---------------------------------------------------------
    def write_line(self, text: str) -> Pending:
        """Sends one text line (the ending is added) and queues it for its
        reply. Returns at once."""
        p = Pending(text=text, sent_at=self.clock())
        self._write(self._wire(text).encode("ascii", "replace") + self.eol)
        if text.strip():  # an empty line earns no reply
            self._queue.append(p)
        else:
            p.abandoned = True
        return p

    def write_rc(self, chars: str) -> None:
        """Sends RC-app bytes: no line ending, no reply expected."""
        self._write(chars.encode("ascii", "replace"))

    def write_raw(self, payload: str, check: Optional[bool] = None) -> List[Pending]:
        """Sends bytes as they are, but for each line they end, which goes
        out checked when `check` (default: the link's `checked`) says so;
        one queue entry per non-empty line (bytes after the last line end
        are RC bytes or a line's start, sent as they are)."""
        check = self.checked if check is None else check
        now = self.clock()
        parts = re.split(r"(\r\n|\r|\n)", payload)  # text, ending, text, ending, ..., rest
        entries = [Pending(text=line, sent_at=now) for line in parts[0:-1:2] if line]
        if check:
            parts = [self._wire(p) if i % 2 == 0 and i + 1 < len(parts) else p for i, p in enumerate(parts)]
        self._write("".join(parts).encode("latin-1", "replace"))
        self._queue.extend(entries)
        return entries

    def _wire(self, text: str) -> str:
        """A line as it is sent: checked unless the link is plain, the line
        is empty, a checked line already, or one RC byte (which acts as it
        arrives and has no checked form; its line end is answered `ok rc`)."""
        if not self.checked or not text.strip() or text.startswith("$") or (len(text) == 1 and text in RC_BYTES):
            return text
        return checked_line(text)

    def _write(self, data: bytes) -> None:
        try:
            self.port.write(data)
            self.port.flush()
        except (serial.SerialException, OSError) as e:
            raise LinkError(f"write failed: {e}") from e

    # -- reading ---------------------------------------------------------
    def poll(self, timeout: float = 0.0) -> List[Event]:
        """Reads what arrived within `timeout` seconds (returns early once
        at least one whole line is there) and returns the lines as events."""
        deadline = self.clock() + timeout
        events: List[Event] = []
        while True:
            self._read_some(max(0.0, deadline - self.clock()))
            events.extend(self._take_lines())
            if events or self.clock() >= deadline:
                return events

    def _read_some(self, wait: float) -> None:
        try:
            n = self.port.in_waiting
            if n:
                self._buf += self.port.read(n)
                return
            if wait <= 0:
                return
            # Blocks at most the port's own timeout (0.05 s from open_port).
            chunk = self.port.read(1)
            if chunk:
                self._buf += chunk
                n = self.port.in_waiting
                if n:
                    self._buf += self.port.read(n)
        except (serial.SerialException, OSError) as e:
            raise LinkError(f"read failed: {e}") from e

    def _take_lines(self) -> List[Event]:
        events = []
        while True:
            # A line ended by CR alone is taken at once; an LF right after it
            # is then the rest of a CR LF, not an empty line.
            if self._skip_lf and self._buf[:1] == b"\n":
                del self._buf[:1]
            if self._buf:
                self._skip_lf = False
            m = re.search(rb"\r\n|\n|\r", self._buf)
            if not m:
                return events
            raw = bytes(self._buf[: m.start()])
            self._skip_lf = m.group() == b"\r"
            del self._buf[: m.end()]
            line = raw.decode("ascii", "replace").strip()
            if line:
                events.append(self._classify(line))

    def _classify(self, line: str) -> Event:
        now = self.clock()
        text, held = split_check(line)
        if held is False:  # shown as it came
            return self._event(Event(time=now, kind="damaged", line=line, checked=False))
        line = text
        kind = kind_of(line)
        ev = Event(time=now, kind=kind, line=line, checked=held)
        if kind in ("ok", "err"):
            ev.reply = parse_reply(line)
            ev.reply.checked = bool(held)
            self._forget_old(now)
            req = self._match(ev.reply)
            if req is not None:
                req.reply = ev.reply
                ev.request = req
                ev.late = req.abandoned
        elif kind == "info":
            self.notices.append(ev)
        return self._event(ev)

    def _event(self, ev: Event) -> Event:
        if self.on_event is not None:
            self.on_event(ev)
        return ev

    def _match(self, reply: Reply) -> Optional[Pending]:
        """The request `reply` answers: the oldest waiting one, except that
        abandoned requests it cannot answer are taken as lost lines and
        dropped. None for a stray reply (fits no request)."""
        for i, req in enumerate(self._queue):
            if plausible(req.text, reply):
                for _ in range(i):
                    self._queue.popleft()
                return self._queue.popleft()
            if not req.abandoned:
                return None
        return None

    def _forget_old(self, now: float) -> None:
        while self._queue and self._queue[0].abandoned and now - self._queue[0].sent_at > self.forget_after_s:
            self._queue.popleft()

    @property
    def waiting(self) -> int:
        """Lines sent whose reply has not arrived."""
        return len(self._queue)

    # -- request/reply ---------------------------------------------------
    def wait_reply(self, req: Pending, timeout: float = 2.0) -> Reply:
        """Polls until `req` has its reply; ReplyTimeout after `timeout` s
        (the request is then abandoned: its late reply will be dropped)."""
        deadline = self.clock() + timeout
        while req.reply is None:
            left = deadline - self.clock()
            if left <= 0:
                req.abandoned = True
                raise ReplyTimeout(f"no reply to {req.text!r} within {timeout:g} s")
            self.poll(left)
        return req.reply

    def command(self, text: str, timeout: float = 2.0) -> Reply:
        """Sends a text line and returns its reply (skipping info lines)."""
        return self.wait_reply(self.write_line(text), timeout)

    def wait_for(self, pattern: str, timeout: float) -> Optional[Event]:
        """The first line matching regex `pattern` within `timeout` s, or None."""
        rx = re.compile(pattern)
        deadline = self.clock() + timeout
        while True:
            left = deadline - self.clock()
            if left <= 0:
                return None
            for ev in self.poll(left):
                if rx.search(ev.line):
                    return ev

    def probe(self, timeout: float, every: float = 0.5) -> bool:
        """Sends `status` every `every` s until one is answered (a board
        still booting ignores or garbles lines); False if none is within
        `timeout` s. Probes still unanswered a moment later are forgotten,
        so they cannot claim the reply of a later status."""
        deadline = self.clock() + timeout
        sent: List[Pending] = []
        answered = False
        while not answered and self.clock() < deadline:
            sent.append(self.write_line("status"))
            sent[-1].abandoned = True
            next_at = min(deadline, self.clock() + every)
            while not answered and self.clock() < next_at:
                self.poll(next_at - self.clock())
                answered = any(p.reply is not None for p in sent)
        if answered:
            # Lines queued while the board booted are answered one by one:
            # wait while their replies keep coming.
            settle = self.clock() + every
            while self.clock() < settle and any(p.reply is None for p in sent):
                before = sum(p.reply is not None for p in sent)
                self.poll(settle - self.clock())
                if sum(p.reply is not None for p in sent) > before:
                    settle = self.clock() + every
        ids = {id(p) for p in sent}
        self._queue = deque(q for q in self._queue if id(q) not in ids)
        return answered

    def wait_ready(self, timeout: float) -> bool:
        """For a board that is booting now: waits for its boot line
        (`info strider <model> ready`), then checks that it answers. Lines
        sent during boot pile up in the UART and, on some firmware builds,
        have upset the start-up, so nothing is sent before the boot line
        unless it never comes (then `status` is probed as a last resort)."""
        deadline = self.clock() + timeout
        self.wait_for(r"^info strider .*ready", timeout)  # missed (already booted?): probing decides
        return self.probe(max(1.0, deadline - self.clock()))

    def wait_standing(self, timeout: float, every: float = 0.25) -> bool:
        """After a boot: asks `status` every `every` s until the robot stands
        (its legs switched on, the stand-up over), or will not stand up by
        itself (relaxed, calibrating, a servo board away; a status without
        those fields, from an older firmware). False if it still rises, or
        has not answered, after `timeout` s."""
        deadline = self.clock() + timeout
        while True:
            try:
                fields = status_fields(self.command("status", max(0.5, min(2.0, deadline - self.clock()))).line)
            except ReplyTimeout:
                fields = None  # no answer (yet): ask again until the deadline
            if fields is not None and not rising(fields):
                return True
            if self.clock() >= deadline:
                return False
            end = min(deadline, self.clock() + every)
            while self.clock() < end:
                self.poll(end - self.clock())

    def close(self) -> None:
        try:
            self.port.close()
        except Exception:  # closing a broken port must not hide the real error
            pass


def status_fields(line: str) -> dict:
    """`ok status a=1 b=x ...` -> {"a": "1", "b": "x"} (the first of a repeated key)."""
    out: dict = {}
    for word in line.split()[2:]:
        key, eq, value = word.partition("=")
        if eq:
            out.setdefault(key, value)
    return out


def rising(fields: dict) -> bool:
    """True while a status says the robot is standing up by itself: its legs
    being switched on or its body rising, not relaxed or calibrating, every
    servo board there."""
    if fields.get("mode") in (None, "relaxed", "calibrating") or fields.get("pca9685", "ok") != "ok":
        return False
    return fields.get("servos") == "starting" or fields.get("state") in ("sitting", "standing_up")


def open_port(url: str, baud: int = 9600, timeout: float = 0.05) -> "serial.SerialBase":
    """A pyserial port for a device path (/dev/ttyACM0, /dev/rfcomm0, a pty
    printed by `vbench --pty`) or a pyserial URL (loop://, socket://...)."""
    try:
        return serial.serial_for_url(url, baudrate=baud, timeout=timeout, write_timeout=5)
    except (serial.SerialException, OSError, ValueError) as e:
        raise LinkError(f"cannot open {url}: {e}") from e
