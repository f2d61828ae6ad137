"""robotctl against a fake robot on a pseudo-terminal, plus its pure parts
(protocol parsing, scripts, the drive logic) with a fake clock.

Run: python -m unittest discover -s test/tools -p 'test_robotctl.py'
(with tools/robotctl on PYTHONPATH or robotctl installed)."""
import io
import json
import os
import subprocess
import sys
import tempfile
import threading
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tools", "robotctl"))
sys.path.insert(0, HERE)

from fake_robot import FakeRobot  # noqa: E402
from robotctl import cli, protocol  # noqa: E402
from robotctl.drive import DriveState  # noqa: E402
from robotctl.link import Link, ReplyTimeout, open_port  # noqa: E402
from robotctl.script import ScriptError, parse_script, play  # noqa: E402


class FakeClock:
    def __init__(self):
        self.t = 0.0

    def __call__(self):
        return self.t


class FakeLink:
    """Records what is written and when, on a manual clock; poll() advances
    the clock instead of sleeping and answers lines with `ok <line>`."""

    def __init__(self, answer=True):
        self.clock = FakeClock()
        self.writes = []  # (time, kind, text)
        self.notices = []
        self.answer = answer
        self.waiting = 0
        self.get_reply = ("ok get gait=trot step_height=20.00 step_length=40.00 cycle=0.80 duty=0.50 swing=ellipse "
                          "height=72.0")
        self.refuse = {}  # line -> its err reply

    class Req:
        def __init__(self, text, t):
            self.text, self.sent_at, self.reply, self.abandoned = text, t, None, False

    def _req(self, text):
        r = FakeLink.Req(text, self.clock.t)
        if self.answer:
            word = text.split()[0] if text.split() else ""
            line = ("ok status mode=walking speed=70 vx=155.0 vy=0.0 wz=0.0 avoid=off sonar=none "
                    "deadman_ms=1000 eeprom=ok") if word == "status" else f"ok {text.strip()}"
            if word == "get":
                line = self.get_reply
            elif text.strip() in self.refuse:
                line = self.refuse[text.strip()]
            r.reply = protocol.parse_reply(line)
        return r

    def write_rc(self, chars):
        self.writes.append((self.clock.t, "rc", chars))

    def write_line(self, text):
        self.writes.append((self.clock.t, "line", text))
        return self._req(text)

    def write_raw(self, payload):
        self.writes.append((self.clock.t, "raw", payload))
        return [self._req(payload) for _ in range(protocol.replies_expected(payload))]

    def wait_reply(self, req, timeout):
        if req.reply is None:
            self.clock.t += timeout
            raise ReplyTimeout("no reply")
        return req.reply

    def poll(self, timeout=0.0):
        self.clock.t += timeout
        return []


class ProtocolTest(unittest.TestCase):
    def test_ok_reply_fields(self):
        r = protocol.parse_reply("ok move vx=100.0 vy=0.0 wz=-60.0")
        self.assertTrue(r.ok)
        self.assertEqual(r.what, "move")
        self.assertEqual(r.fields, {"vx": 100.0, "vy": 0.0, "wz": -60.0})

    def test_err_reply_code_and_reason(self):
        r = protocol.parse_reply("err 5 out of range")
        self.assertFalse(r.ok)
        self.assertEqual(r.code, 5)
        self.assertEqual(r.reason, "out of range")
        self.assertEqual(protocol.ERROR_CODES[r.code], r.reason)
        r = protocol.parse_reply("err 23 unknown gait: walk trot pace crawl")
        self.assertEqual((r.code, r.reason, r.valid), (23, "unknown gait", "walk trot pace crawl"))

    def test_error_codes_as_the_protocol_doc_lists_them(self):
        # docs/protocol.md's error table: `| code | `reason` / `other reason` | ...`;
        # robotctl knows every code, by a reason the row names.
        rows = {}
        with open(os.path.join(ROOT, "docs", "protocol.md"), encoding="utf-8") as f:
            for line in f:
                cells = line.split(" | ")
                if line.startswith("| ") and len(cells) > 2 and cells[0][2:].strip().isdigit():
                    rows[int(cells[0][2:])] = cells[1]
        self.assertGreaterEqual(len(rows), 20)
        self.assertEqual(sorted(protocol.ERROR_CODES), sorted(rows))
        for code, reason in protocol.ERROR_CODES.items():
            self.assertIn(f"`{reason}`", rows[code], code)

    def test_kinds(self):
        self.assertEqual(protocol.kind_of("info deadman stop"), "info")
        self.assertEqual(protocol.kind_of("ok"), "ok")
        self.assertEqual(protocol.kind_of("okay"), "other")
        self.assertIsNone(protocol.parse_reply("info avoid blocked"))

    def test_status_fields_typed(self):
        r = protocol.parse_reply("ok status mode=walking speed=50 vx=100.0 vy=0.0 wz=0.0 avoid=forward "
                                 "sonar=ok dist_mm=812 deadman_ms=1000 eeprom=ok")
        st = protocol.parse_status(r)
        self.assertEqual(st["mode"], "walking")
        self.assertEqual(st["speed"], 50)
        self.assertIsInstance(st["speed"], int)
        self.assertEqual(st["vx"], 100.0)
        self.assertEqual(st["dist_mm"], 812)
        self.assertEqual(st["eeprom"], "ok")
        self.assertIn("sonar=ok 812 mm", protocol.status_summary(st))
        with self.assertRaises(ValueError):
            protocol.parse_status(protocol.parse_reply("ok stop"))

    def test_check_line(self):
        self.assertIsNone(protocol.check_line("walk 100"))
        self.assertIn("63", protocol.check_line("walk " + "1" * 70))
        self.assertIn("uppercase", protocol.check_line("Walk 100"))
        self.assertIn("ASCII", protocol.check_line("walk \u00e9"))

    def test_check_line_counts_the_check(self):
        self.assertIsNone(protocol.check_line("walk " + "1" * 52, checked=True))
        self.assertIn("57", protocol.check_line("walk " + "1" * 53, checked=True))

    def test_line_checks(self):
        # CRC-16/CCITT-FALSE, as the robot's line_check.h (docs/protocol.md).
        self.assertEqual(protocol.crc16("123456789"), 0x29B1)
        self.assertEqual(protocol.checked_line("deadman off"), "$deadman off*cb77")
        self.assertEqual(protocol.checked_line("walk 100"), "$walk 100*1a94")
        self.assertEqual(protocol.split_check("ok move vx=100.0 vy=0.0 wz=0.0*e95c"),
                         ("ok move vx=100.0 vy=0.0 wz=0.0", True))
        self.assertEqual(protocol.split_check("ok speed pct=40*C92C"), ("ok speed pct=40", True))
        self.assertEqual(protocol.split_check("ok speed pct=41*c92c"), ("ok speed pct=41", False))
        self.assertEqual(protocol.split_check("ok speed pct=40"), ("ok speed pct=40", None))
        self.assertEqual(protocol.split_check("ok x*c92"), ("ok x*c92", None))
        self.assertEqual(protocol.ERROR_CODES[9], "bad checksum")
        self.assertEqual(protocol.ERROR_CODES[10], "bytes lost")
        self.assertEqual(protocol.ERROR_CODES[11], "checksum required")

    def test_unescape_and_reply_count(self):
        self.assertEqual(protocol.unescape(r"stop\r\nstatus\n"), "stop\r\nstatus\n")
        self.assertEqual(protocol.replies_expected("stop\r\nstatus\n"), 2)
        self.assertEqual(protocol.replies_expected("FFS"), 0)
        self.assertEqual(protocol.replies_expected("\n\r\n"), 0)
        self.assertEqual(protocol.replies_expected("walk 1\rwalk 2\r"), 2)


class ScriptTest(unittest.TestCase):
    def test_forms(self):
        steps = parse_script("# demo\nrobot sprawl8\nat 0 send gait trot\nat 1.5 send walk 100  # go\n"
                             "+2 rc S\nwait 0.5\nstatus\nat 4 send stop\\r\n")
        kinds = [(s.kind, s.at, s.after) for s in steps]
        self.assertEqual(kinds, [("skip", None, None), ("send", 0.0, None), ("send", 1.5, None), ("rc", None, 2.0),
                                 ("wait", None, 0.5), ("send", None, None), ("send", 4.0, None)])
        self.assertEqual(steps[1].payload, "gait trot\n")
        self.assertEqual(steps[6].payload, "stop\r")  # an explicit ending is kept as it is

    def test_errors(self):
        for bad in ("at x send stop", "at 1 jump", "at 2 send a\nat 1 send b", "+1 send"):
            with self.assertRaises(ScriptError, msg=bad):
                parse_script(bad)

    def test_play_schedule_on_a_fake_clock(self):
        link = FakeLink()
        steps = parse_script("at 1 send walk 100\n+0.5 rc F\nwait 1\nstatus\nat 5 send stop\n")
        log = []
        res = play(link, steps, log.append)
        self.assertEqual([(round(t, 6), k, p) for t, k, p in link.writes],
                         [(1.0, "raw", "walk 100\n"), (1.5, "rc", "F"), (2.5, "raw", "status\n"),
                          (5.0, "raw", "stop\n")])
        self.assertEqual((res.sent, res.errors, res.timeouts), (3, 0, 0))
        self.assertTrue(any("< ok walk 100" in line for line in log))

    def test_play_counts_timeouts(self):
        link = FakeLink(answer=False)
        res = play(link, parse_script("stop\nstatus\n"), lambda t: None, timeout=0.5)
        self.assertEqual(res.timeouts, 2)


class DriveTest(unittest.TestCase):
    def make(self, **kw):
        link = FakeLink()
        return link, DriveState(link, **kw)

    def rc_writes(self, link):
        return [(round(t, 6), p) for t, k, p in link.writes if k == "rc"]

    def test_latch_repeats_until_space(self):
        link, ds = self.make(repeat_s=0.25, status_period_s=0)
        ds.key("UP")
        for _ in range(10):  # 1 s of ticks
            link.clock.t += 0.1
            ds.tick()
        ds.key(" ")
        self.assertEqual(ds.motion, "S")
        w = self.rc_writes(link)
        self.assertEqual(w[0], (0.0, "F"))
        self.assertEqual(w[-1][1], "S")
        repeats = [p for _, p in w[1:-1]]
        self.assertEqual(set(repeats), {"F"})
        self.assertEqual(len(repeats), 3)  # at 0.3, 0.6, 0.9 s (ticks of 0.1 s, period 0.25 s)

    def test_key_map(self):
        link, ds = self.make(status_period_s=0)
        for k in ("w", "a", "s", "d", "z", "c", "[", "]", "LEFT", "RIGHT", "DOWN", "G"):
            ds.key(k)
        self.assertEqual("".join(p for _, p in self.rc_writes(link)), "FLBRGIHJLRBG")

    def test_hold_mode_stops_on_release(self):
        link, ds = self.make(latch=False, release_s=0.6, repeat_s=0.25, status_period_s=0)
        ds.key("w")
        for _ in range(3):  # key repeat of the terminal every 0.1 s
            link.clock.t += 0.1
            ds.key("w")
            ds.tick()
        self.assertEqual(ds.motion, "F")
        for _ in range(7):
            link.clock.t += 0.1
            ds.tick()
        self.assertEqual(ds.motion, "S")
        self.assertEqual(self.rc_writes(link)[-1][1], "S")

    def test_speed_and_quit(self):
        link, ds = self.make(status_period_s=0)
        ds.key("7")
        ds.key("q")
        self.assertEqual(ds.speed_pct, 100)
        ds.key("ESC")
        self.assertTrue(ds.quit)
        self.assertEqual("".join(p for _, p in self.rc_writes(link)), "7qS")

    def test_status_refresh(self):
        link, ds = self.make(status_period_s=1.0)
        ds.tick()
        self.assertEqual(ds.status["mode"], "walking")
        self.assertIn("mode=walking", ds.status_line)
        n = sum(1 for _, k, p in link.writes if p == "status")
        link.clock.t += 0.5
        ds.tick()
        self.assertEqual(sum(1 for _, k, p in link.writes if p == "status"), n)
        link.clock.t += 0.6
        ds.tick()
        self.assertEqual(sum(1 for _, k, p in link.writes if p == "status"), n + 1)

    def test_tune_keys_step_the_gaits_parameters(self):
        link, ds = self.make(status_period_s=0)
        ds.key("u")  # nothing to step from yet: asks get first
        ds.tick()
        self.assertEqual(ds.tune["step_height"], "20.00")
        self.assertIn("gait=trot", ds.tune_line)
        for k in ("u", "k", "o", "y", "h"):
            ds.key(k)
            ds.tick()
        link.refuse["set swing cycloid"] = "err 25 swing not under the model's own swing: semicircle ellipse"
        ds.key("n")  # ellipse -> cycloid, refused: the next press tries the one after
        ds.tick()
        self.assertEqual(ds.last_reply, "err 25 swing not under the model's own swing: semicircle ellipse")
        ds.key("n")
        ds.tick()
        ds.key("p")
        ds.tick()
        sets = [p for _, k, p in link.writes if k == "line" and p != "get"]
        self.assertEqual(sets, ["set step_height 21.00", "set step_length 35.00", "set cycle 0.75", "set duty 0.51",
                                "set duty 0.49", "set swing cycloid", "set swing parabola", "save"])
        self.assertEqual(ds.last_reply, "ok save")
        # After each set the values are asked again; no RC byte was sent.
        self.assertEqual(sum(1 for _, k, p in link.writes if p == "get"), 1 + len(sets))
        self.assertEqual(self.rc_writes(link), [])

    def test_typed_line_shows_its_reply(self):
        link, ds = self.make(status_period_s=0)
        ds.send_line("gait trot")
        ds.tick()
        self.assertEqual(ds.last_reply, "ok gait trot")


class LinkOnPtyTest(unittest.TestCase):
    def setUp(self):
        self.robot = FakeRobot()
        self.link = Link(open_port(self.robot.path, 9600))

    def tearDown(self):
        self.link.close()
        self.robot.close()

    def test_command_ok_and_err(self):
        r = self.link.command("walk 100")
        self.assertTrue(r.ok)
        self.assertEqual(r.fields["vx"], 100.0)
        r = self.link.command("walk 900")
        self.assertEqual((r.ok, r.code, r.reason), (False, 5, "out of range"))
        r = self.link.command("jump")
        self.assertEqual(r.code, 1)
        self.assertEqual(self.robot.lines, ["walk 100", "walk 900", "jump"])

    def test_lines_go_checked_and_replies_are_checked(self):
        r = self.link.command("walk 100")
        self.assertEqual(r.line, "ok move vx=100.0 vy=0.0 wz=0.0")
        self.assertTrue(r.checked)
        self.assertEqual(self.robot.checked, [True])
        # A line written checked already is not wrapped twice.
        r = self.link.command("$deadman off*cb77")
        self.assertEqual(self.robot.lines[-1], "deadman off")
        self.assertEqual(self.robot.checked, [True, True])

    def test_wait_standing(self):
        # A robot that stands (or an older firmware without state=): at once.
        self.assertTrue(self.link.wait_standing(2.0))
        # One still rising, then standing.
        self.robot.status_line = lambda: "ok status mode=standing speed=50 state=standing_up servos=on pca9685=ok"
        threading.Timer(0.6, lambda: setattr(self.robot, "status_line",
                                             lambda: "ok status mode=standing state=standing servos=on")).start()
        t0 = time.monotonic()
        self.assertTrue(self.link.wait_standing(5.0, every=0.1))
        self.assertGreater(time.monotonic() - t0, 0.5)
        # One that does not answer: not taken for standing.
        self.robot.withhold = {"status"}
        t0 = time.monotonic()
        self.assertFalse(self.link.wait_standing(1.0))
        self.assertLess(time.monotonic() - t0, 3.0)

    def test_rc_letter_line_goes_plain(self):
        r = self.link.command("F")
        self.assertEqual(r.line, "ok rc F")
        self.assertEqual(self.robot.lines, ["F"])
        self.assertEqual(self.robot.checked, [False])

    def test_plain_link_sends_plain_lines(self):
        self.link.checked = False
        r = self.link.command("walk 100")
        self.assertEqual(r.line, "ok move vx=100.0 vy=0.0 wz=0.0")
        self.assertFalse(r.checked)
        self.assertEqual(self.robot.checked, [False])

    def test_damaged_reply_answers_nothing(self):
        self.robot.break_check = {"speed"}
        seen = []
        self.link.on_event = seen.append
        with self.assertRaises(ReplyTimeout):
            self.link.command("speed 40", timeout=0.5)
        self.assertEqual([e.kind for e in seen], ["damaged"])
        self.assertTrue(seen[0].line.startswith("ok speed pct=40*"))
        self.assertTrue(self.link.command("stop").checked)  # the link goes on

    def test_raw_payload_lines_are_checked(self):
        reqs = self.link.write_raw("stop\r\nwalk 10\nF")
        self.assertEqual([self.link.wait_reply(q).line for q in reqs], ["ok stop", "ok move vx=10.0 vy=0.0 wz=0.0"])
        self.assertEqual(self.robot.checked, [True, True])
        deadline = time.monotonic() + 2
        while not self.robot.rc and time.monotonic() < deadline:
            time.sleep(0.01)
        self.assertEqual(self.robot.rc, ["F"])  # RC bytes stay bytes
        reqs = self.link.write_raw("stop\n", check=False)
        self.link.wait_reply(reqs[0])
        self.assertEqual(self.robot.checked, [True, True, False])

    def test_info_lines_are_not_replies(self):
        self.robot.info_before = ["info avoid sidestep", "info deadman stop"]
        r = self.link.command("stop")
        self.assertEqual(r.line, "ok stop")
        self.assertEqual([e.line for e in self.link.notices], ["info avoid sidestep", "info deadman stop"])

    def test_fragmented_and_delayed_replies(self):
        self.robot.fragment = True
        self.robot.delay_s = 0.05
        replies = [self.link.command(c).line for c in ("status", "walk 50", "stop")]
        self.assertTrue(replies[0].startswith("ok status mode=standing"))
        self.assertEqual(replies[1:], ["ok move vx=50.0 vy=0.0 wz=0.0", "ok stop"])

    def test_pipelined_lines_pair_in_order(self):
        reqs = [self.link.write_line(c) for c in ("walk 10", "jump", "stop", "status")]
        got = [self.link.wait_reply(r).line.split()[0:2] for r in reqs]
        self.assertEqual(got, [["ok", "move"], ["err", "1"], ["ok", "stop"], ["ok", "status"]])

    def test_late_reply_is_not_taken_for_the_next(self):
        self.robot.late = {"walk": 0.6}
        with self.assertRaises(ReplyTimeout):
            self.link.command("walk 100", timeout=0.2)
        r = self.link.command("stop", timeout=2.0)
        self.assertEqual(r.line, "ok stop")  # the late "ok move" was dropped

    def test_lost_line_does_not_shift_the_pairing(self):
        self.robot.withhold = {"stop"}  # this line is lost on the way
        with self.assertRaises(ReplyTimeout):
            self.link.command("stop", timeout=0.2)
        self.assertEqual(self.link.command("walk 10").line, "ok move vx=10.0 vy=0.0 wz=0.0")
        self.assertEqual(self.link.command("status").what, "status")

    def test_stray_reply_is_not_taken(self):
        self.robot.notice("ok status mode=standing")  # nobody asked
        time.sleep(0.05)
        self.assertEqual(self.link.command("walk 20").fields["vx"], 20.0)

    def test_probe_until_the_board_answers(self):
        answered = []
        real = self.robot.answer

        def booting(line):  # the first two lines arrive during boot: garbage back
            answered.append(line)
            return "\x00\x7f boot" if len(answered) <= 2 else real(line)
        self.robot.answer = booting
        self.assertTrue(self.link.probe(5.0, every=0.2))
        self.assertEqual(self.link.command("stop").line, "ok stop")

    def test_rc_bytes_get_no_reply(self):
        self.link.write_rc("FF5S")
        self.assertEqual(self.link.command("status").what, "status")
        self.assertEqual(self.robot.rc, list("FF5S"))
        r = self.link.command("F")  # an RC letter on its own line
        self.assertEqual(r.line, "ok rc F")

    def test_lf_only_endings(self):
        self.robot.eol = b"\n"
        self.assertEqual(self.link.command("stop").line, "ok stop")
        self.robot.eol = b"\r"
        self.assertEqual(self.link.command("stop").line, "ok stop")
        self.assertEqual(self.link.command("walk 1").line, "ok move vx=1.0 vy=0.0 wz=0.0")


class CliTest(unittest.TestCase):
    def setUp(self):
        self.robot = FakeRobot()

    def tearDown(self):
        self.robot.close()

    def run_cli(self, *args):
        out = io.StringIO()
        rc = cli.main(["--port", self.robot.path, "--timeout", "1", *args], out=out)
        return rc, out.getvalue()

    def test_send(self):
        rc, out = self.run_cli("send", "walk 100", "stop")
        self.assertEqual(rc, cli.EXIT_OK)
        self.assertEqual(out.splitlines(), ["ok move vx=100.0 vy=0.0 wz=0.0", "ok stop"])

    def test_send_checked_plain_and_raw(self):
        rc, out = self.run_cli("send", "speed 40")
        self.assertEqual((rc, out.strip()), (0, "ok speed pct=40"))
        rc, out = self.run_cli("--plain", "send", "speed 41")
        self.assertEqual((rc, out.strip()), (0, "ok speed pct=41"))
        rc, out = self.run_cli("send", "--raw", r"speed 42\n")
        self.assertEqual((rc, out.strip()), (0, "ok speed pct=42"))
        self.assertEqual(self.robot.checked, [True, False, False])

    def test_rising_reads_the_status(self):
        from robotctl.link import rising, status_fields
        f = status_fields("ok status mode=standing speed=50 gait=trot state=standing_up servos=on pca9685=ok")
        self.assertEqual((f["mode"], f["state"], f["servos"]), ("standing", "standing_up", "on"))
        self.assertTrue(rising(f))
        self.assertTrue(rising(status_fields("ok status mode=standing state=sitting servos=starting")))
        self.assertFalse(rising(status_fields("ok status mode=standing state=standing servos=on")))
        self.assertFalse(rising(status_fields("ok status mode=relaxed state=sitting servos=off")))
        self.assertFalse(rising(status_fields("ok status mode=standing state=sitting servos=starting pca9685=0x41")))
        self.assertFalse(rising(status_fields("ok status mode=standing speed=50")))  # older firmware: no state

    def test_send_err_exit_status(self):
        rc, out = self.run_cli("send", "walk 1000")
        self.assertEqual(rc, cli.EXIT_ERR_REPLY)
        self.assertEqual(out.strip(), "err 5 out of range: walk -500..500")

    def test_send_options_after_the_command(self):
        out = io.StringIO()
        rc = cli.main(["send", "--port", self.robot.path, "stop"], out=out)
        self.assertEqual((rc, out.getvalue().strip()), (0, "ok stop"))

    def test_send_timeout(self):
        self.robot.withhold = {"stop"}
        rc, _ = self.run_cli("--timeout", "0.2", "send", "stop")
        self.assertEqual(rc, cli.EXIT_TIMEOUT)

    def test_send_rc(self):
        rc, _ = self.run_cli("send", "--rc", "F7")
        self.assertEqual(rc, 0)
        deadline = time.monotonic() + 2
        while len(self.robot.rc) < 2 and time.monotonic() < deadline:
            time.sleep(0.01)
        self.assertEqual(self.robot.rc, ["F", "7"])
        rc, _ = self.run_cli("send", "--rc", "walk")
        self.assertEqual(rc, cli.EXIT_USAGE)

    def test_status_json(self):
        self.robot.mode = "walking"
        rc, out = self.run_cli("status", "--json")
        self.assertEqual(rc, 0)
        st = json.loads(out)
        self.assertEqual((st["mode"], st["speed"], st["dist_mm"]), ("walking", 50, 812))

    def test_status_table(self):
        rc, out = self.run_cli("status")
        self.assertEqual(rc, 0)
        self.assertIn("mode        standing", out)

    def test_play(self):
        with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
            f.write("at 0 send walk 100\nat 0.1 rc S\n+0.05 send status\nbogus\n")
        try:
            rc, out = self.run_cli("play", f.name)
        finally:
            os.unlink(f.name)
        self.assertEqual(rc, cli.EXIT_ERR_REPLY)  # `bogus` earns err 1
        self.assertIn("< ok move vx=100.0", out)
        self.assertIn("< err 1 unknown command", out)
        self.assertIn("# 3 lines, 1 err replies, 0 timeouts", out)
        self.assertEqual(self.robot.rc, ["S"])

    def test_bad_port_and_no_port(self):
        out = io.StringIO()
        self.assertEqual(cli.main(["--port", "/nonexistent/tty", "send", "stop"], out=out), cli.EXIT_LINK)
        env = os.environ.pop("ROBOTCTL_PORT", None)
        try:
            self.assertEqual(cli.main(["send", "stop"], out=out), cli.EXIT_USAGE)
        finally:
            if env is not None:
                os.environ["ROBOTCTL_PORT"] = env

    def test_module_entry_point(self):
        env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "tools", "robotctl"))
        p = subprocess.run([sys.executable, "-m", "robotctl", "--port", self.robot.path, "send", "stop"],
                           capture_output=True, text=True, env=env, timeout=30)
        self.assertEqual((p.returncode, p.stdout.strip()), (0, "ok stop"), p.stderr)


class SimPortTest(unittest.TestCase):
    """Where `sim:` finds vbench and the firmware."""

    def test_lookup(self):
        from robotctl import sim
        with tempfile.TemporaryDirectory() as tmp:
            build = sim.pathlib.Path(tmp)
            (build / "tools" / "vbench").mkdir(parents=True)
            (build / "src").mkdir()
            (build / "tools" / "vbench" / "vbench").write_text("")
            (build / "src" / "strider_firmware_sprawl8.elf").write_text("")
            (build / "src" / "strider_firmware_dog12.elf").write_text("")
            self.assertEqual(sim.find_vbench(None, build), str(build / "tools" / "vbench" / "vbench"))
            self.assertEqual(sim.find_vbench("/x/vbench", build), "/x/vbench")
            self.assertEqual(sim.find_elf("", None, build), str(build / "src" / "strider_firmware_sprawl8.elf"))
            self.assertEqual(sim.find_elf("dog12", None, build), str(build / "src" / "strider_firmware_dog12.elf"))
            self.assertIsNone(sim.find_elf("hexapod18", None, build))
            self.assertEqual(sim.find_elf("/a/b.elf", None, build), "/a/b.elf")
            self.assertEqual(sim.build_dir(tmp), build)

    def test_missing_firmware_is_a_link_error(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = io.StringIO()
            rc = cli.main(["--port", "sim:hexapod18", "--build-dir", tmp, "--vbench", "/bin/true", "send", "status"],
                          out=out)
        self.assertEqual(rc, cli.EXIT_LINK)


class DriveScreenTest(unittest.TestCase):
    """`robotctl drive` on a pseudo-terminal: keys in, RC bytes and lines out."""

    def test_keys_reach_the_robot(self):
        import select
        robot = FakeRobot()
        master, slave = os.openpty()
        env = dict(os.environ, TERM="xterm", LINES="30", COLUMNS="120",
                   PYTHONPATH=os.path.join(ROOT, "tools", "robotctl"))
        p = subprocess.Popen([sys.executable, "-m", "robotctl", "--port", robot.path, "drive", "--status-period", "0.3"],
                             stdin=slave, stdout=slave, stderr=slave, env=env, close_fds=True)
        os.close(slave)
        screen = bytearray()

        def pump(seconds):
            end = time.monotonic() + seconds
            while time.monotonic() < end:
                r, _, _ = select.select([master], [], [], 0.05)
                if r:
                    try:
                        screen.extend(os.read(master, 65536))
                    except OSError:
                        return

        def until(cond, limit=10.0):
            end = time.monotonic() + limit
            while not cond() and time.monotonic() < end:
                pump(0.05)

        try:
            until(lambda: b"mode=standing" in screen)
            os.write(master, b"w")
            until(lambda: "F" in robot.rc)
            os.write(master, b"7 ")
            until(lambda: "S" in robot.rc)
            os.write(master, b"tgait trot\r")
            until(lambda: "gait trot" in robot.lines)
            until(lambda: b"ok gait" in screen or b"err 1" in screen, 3.0)
            os.write(master, b"Q")
            p.wait(10)
        finally:
            if p.poll() is None:
                p.kill()
                p.wait()
            os.close(master)
            robot.close()
        self.assertEqual(p.returncode, 0)
        rc = "".join(robot.rc)
        self.assertEqual(rc[0], "F")
        self.assertIn("7", rc)
        self.assertEqual(rc[-1], "S")  # quitting stops the robot
        self.assertIn("gait trot", robot.lines)
        self.assertIn(b"mode=standing", bytes(screen))  # the status line was drawn


if __name__ == "__main__":
    unittest.main()
