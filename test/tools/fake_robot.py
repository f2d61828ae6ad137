"""A tiny scripted robot behind a pseudo-terminal, for robotctl's tests.

It speaks the shape of docs/protocol.md: RC bytes between lines are recorded
and get no reply; each non-empty text line gets one reply from `answer()`, a
checked line (`$text*hhhh`) a checked reply; `info` notices can be pushed at
any time; replies can be delayed, withheld, written in fragments to mimic an
HC-05 that buffers, or sent with a broken check.
"""
import binascii
import os
import re
import queue
import select
import threading
import time
import tty

RC = set("FBLRGIHJS0123456789q")


class FakeRobot:
    def __init__(self, eol=b"\r\n"):
        self.master, self.slave = os.openpty()
        tty.setraw(self.slave)
        self.path = os.ttyname(self.slave)
        self.eol = eol
        self.lines = []          # text lines received (checked ones without their check)
        self.checked = []        # per line: it came checked (and the check held)
        self.break_check = set() # commands whose checked reply gets a wrong check
        self.rc = []             # RC bytes received between lines
        self.delay_s = 0.0       # before each reply
        self.fragment = False    # write replies a few bytes at a time
        self.withhold = set()    # commands never answered
        self.late = {}           # command -> extra delay before its reply [s]
        self.info_before = []    # notices written before the next reply
        self.mode = "standing"
        self.speed = 50
        self.vx = 0.0
        self._cur = None
        self._stop = threading.Event()
        self._lock = threading.Lock()
        self._replies = queue.Queue()
        self._thread = threading.Thread(target=self._run, daemon=True)
        self._thread.start()
        self._writer = threading.Thread(target=self._replier, daemon=True)
        self._writer.start()

    # -- replies -------------------------------------------------------------
    def status_line(self):
        return (f"ok status mode={self.mode} speed={self.speed} vx={self.vx:.1f} vy=0.0 wz=0.0 "
                f"avoid=forward sonar=ok dist_mm=812 deadman_ms=1000 eeprom=ok")

    def answer(self, line):
        words = line.split()
        cmd = words[0]
        if len(line) > 63:
            return "err 6 line too long: at most 63 bytes"
        if cmd == "status":
            return self.status_line()
        if cmd == "walk":
            if len(words) < 2:
                return "err 3 missing argument: walk -500..500"
            try:
                v = float(words[1])
            except ValueError:
                return "err 2 bad argument: walk -500..500"
            if abs(v) > 500:
                return "err 5 out of range: walk -500..500"
            self.vx = v
            self.mode = "walking" if v else "standing"
            return f"ok move vx={v:.1f} vy=0.0 wz=0.0"
        if cmd == "stop":
            self.vx, self.mode = 0.0, "standing"
            return "ok stop"
        if cmd == "speed":
            self.speed = int(words[1])
            return f"ok speed pct={self.speed}"
        if len(words) == 1 and len(cmd) == 1 and cmd in RC:
            return f"ok rc {cmd}"
        return "err 1 unknown command: walk stop speed status"

    # -- io ------------------------------------------------------------------
    def write(self, data: bytes):
        with self._lock:
            if self.fragment:
                for i in range(0, len(data), 3):
                    os.write(self.master, data[i:i + 3])
                    time.sleep(0.002)
            else:
                os.write(self.master, data)

    def notice(self, text):
        self.write(text.encode() + self.eol)

    def _replier(self):
        # One queue, one writer: replies leave in the order of the lines,
        # however long each one is held back (like a buffering HC-05).
        while not self._stop.is_set():
            try:
                line, delay, checked = self._replies.get(timeout=0.05)
            except queue.Empty:
                continue
            if delay > 0:
                time.sleep(delay)
            if not self._stop.is_set():
                reply = self.answer(line) if line is not None else "err 9 bad checksum"
                if checked:
                    crc = binascii.crc_hqx(reply.encode(), 0xFFFF)
                    if line is not None and line.split()[0] in self.break_check:
                        crc ^= 1
                    reply += f"*{crc:04x}"
                self.write(reply.encode() + self.eol)

    def _on_line(self, line):
        checked = line.startswith("$")
        if checked:
            m = re.match(r"^\$(.*)\*([0-9A-Fa-f]{4})$", line)
            if not m or binascii.crc_hqx(m.group(1).encode("latin-1"), 0xFFFF) != int(m.group(2), 16):
                self._replies.put((None, self.delay_s, True))
                return
            line = m.group(1)
        self.lines.append(line)
        self.checked.append(checked)
        cmd = line.split()[0]
        if cmd in self.withhold:
            return
        for n in self.info_before:
            self.notice(n)
        self.info_before = []
        self._replies.put((line, self.delay_s + self.late.get(cmd, 0.0), checked))

    def _on_byte(self, c):
        if self._cur is None:
            if c in "\r\n":
                return
            if c in RC and not ("a" <= c <= "z" and c != "q"):
                self.rc.append(c)
                if c in "FBLRGIHJ":
                    self.mode = "walking"
                elif c == "S":
                    self.mode = "standing"
                self._last_rc = c
                self._cur = ""  # an RC byte may still be a line of its own: "F\n"
                self._rc_pending = c
                return
            self._cur = c
            self._rc_pending = None
            return
        if c in "\r\n":
            if self._cur:
                self._on_line(self._cur)
            elif getattr(self, "_rc_pending", None):
                self._on_line(self._rc_pending)
            self._cur = None
            self._rc_pending = None
            return
        if getattr(self, "_rc_pending", None) and self._cur == "":
            # The RC byte stood alone: this byte starts afresh.
            self._cur = None
            self._rc_pending = None
            self._on_byte(c)
            return
        self._cur += c

    def _run(self):
        while not self._stop.is_set():
            r, _, _ = select.select([self.master], [], [], 0.02)
            if not r:
                continue
            try:
                data = os.read(self.master, 256)
            except OSError:
                return
            for b in data.decode("latin-1"):
                self._on_byte(b)

    def close(self):
        self._stop.set()
        self._thread.join(1)
        self._writer.join(1)
        for fd in (self.master, self.slave):
            try:
                os.close(fd)
            except OSError:
                pass
