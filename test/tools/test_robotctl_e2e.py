"""robotctl against the real firmware on the virtual Mega (`vbench --pty`).

Needs $STRIDER_VBENCH and $STRIDER_ELF (ctest sets both to the build's
vbench and firmware ELF); skipped, with the reason, when either is missing.
"""
import io
import json
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools", "robotctl"))

from robotctl import cli, protocol  # noqa: E402
from robotctl.link import Link, open_port  # noqa: E402
from robotctl.sim import VirtualMega  # noqa: E402

STATUS_KEYS = {"mode", "speed", "vx", "vy", "wz", "avoid", "sonar", "deadman_ms", "eeprom"}


def missing():
    vb, elf = os.environ.get("STRIDER_VBENCH", ""), os.environ.get("STRIDER_ELF", "")
    if not vb or not os.access(vb, os.X_OK):
        return f"vbench not built ({vb or '$STRIDER_VBENCH unset'})"
    if not elf or not os.path.isfile(elf):
        return f"firmware ELF not built ({elf or '$STRIDER_ELF unset'})"
    return None


@unittest.skipIf(missing(), missing() or "")
class VirtualMegaE2E(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.vm = VirtualMega(os.environ["STRIDER_VBENCH"], os.environ["STRIDER_ELF"],
                             eeprom=os.path.join(cls.tmp.name, "eeprom.bin"))
        cls.pty = cls.vm.start()
        cls.link = Link(open_port(cls.pty, 9600))
        if not cls.link.wait_ready(30.0):
            cls.tearDownClass()
            raise AssertionError("the firmware never answered `status`: " + " | ".join(cls.vm.output))

    @classmethod
    def tearDownClass(cls):
        cls.link.close()
        cls.vm.stop()
        cls.tmp.cleanup()

    def status(self):
        return protocol.parse_status(self.link.command("status", 3.0))

    def test_1_status_fields(self):
        st = self.status()
        self.assertTrue(STATUS_KEYS <= set(st), st)
        self.assertIn(st["mode"], ("standing", "walking", "relaxed", "calibrating"))
        self.assertIn(st["eeprom"], ("ok", "empty", "corrupt", "old_version", "invalid"))

    def test_2_text_commands(self):
        self.assertEqual(self.link.command("avoid off", 3.0).line, "ok avoid off")
        r = self.link.command("walk 100", 3.0)
        self.assertEqual(r.line, "ok move vx=100.0 vy=0.0 wz=0.0")
        st = self.status()
        self.assertEqual(st["mode"], "walking")
        self.assertEqual(self.link.command("stop", 3.0).line, "ok stop")
        self.assertEqual(self.status()["mode"], "standing")
        r = self.link.command("jump", 3.0)
        self.assertEqual((r.ok, r.code, r.reason), (False, 1, "unknown command"))
        r = self.link.command("walk 900", 3.0)
        self.assertEqual((r.code, r.reason), (5, "out of range"))
        self.assertEqual(self.link.command("speed 70", 3.0).line, "ok speed pct=70")

    def test_2a_checked_lines(self):
        # robotctl sends checked lines; the firmware answers them checked,
        # and takes `deadman off` from a checked line only.
        r = self.link.command("speed 60", 3.0)
        self.assertEqual((r.line, r.checked), ("ok speed pct=60", True))
        r = self.link.command("deadman off", 3.0)
        self.assertEqual((r.line, r.checked), ("ok deadman off", True))
        self.assertEqual(self.status()["deadman_ms"], 0)
        r = self.link.command("S", 3.0)  # an RC letter on its own line stays plain
        self.assertEqual((r.line, r.checked), ("ok rc S", False))
        self.link.checked = False
        try:
            r = self.link.command("deadman off", 3.0)
            self.assertEqual((r.code, r.reason, r.checked), (11, "checksum required", False))
            self.assertEqual(self.link.command("deadman 1000", 3.0).line, "ok deadman ms=1000")
        finally:
            self.link.checked = True

    def test_2b_pipelined_lines_pair_in_order(self):
        reqs = [self.link.write_line(t) for t in ("speed 40", "jump", "status", "stop")]
        got = [self.link.wait_reply(r, 5.0) for r in reqs]
        self.assertEqual(got[0].line, "ok speed pct=40")
        self.assertEqual(got[1].code, 1)
        self.assertEqual(got[2].what, "status")
        self.assertEqual(protocol.parse_status(got[2])["speed"], 40)
        self.assertEqual(got[3].line, "ok stop")

    def test_3_rc_bytes_and_deadman(self):
        self.link.command("avoid off", 3.0)
        self.link.write_rc("F")
        self.assertEqual(self.status()["mode"], "walking")
        self.link.write_rc("S")
        self.assertEqual(self.status()["mode"], "standing")
        # Silence while walking: the deadman (1000 ms default) stops it.
        self.link.command("deadman 1000", 3.0)
        self.link.notices.clear()
        self.link.write_rc("F")
        ev = self.link.wait_for(r"^info deadman stop", 5.0)
        self.assertIsNotNone(ev, "no `info deadman stop` within 5 s of silence")
        self.assertEqual(self.status()["mode"], "standing")

    def test_4_cli_on_the_pty(self):
        out = io.StringIO()
        rc = cli.main(["--port", self.pty, "--timeout", "3", "send", "stop", "status"], out=out)
        lines = out.getvalue().splitlines()
        self.assertEqual(rc, cli.EXIT_OK, lines)
        self.assertEqual(lines[0], "ok stop")
        self.assertTrue(lines[1].startswith("ok status mode="), lines)
        with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
            f.write("at 0 send avoid off\n+0.2 rc F\n+0.3 send status\n+0.2 send stop\nat 1.0 send bogus\n")
        try:
            out = io.StringIO()
            rc = cli.main(["--port", self.pty, "--timeout", "3", "play", f.name], out=out)
        finally:
            os.unlink(f.name)
        text = out.getvalue()
        self.assertEqual(rc, cli.EXIT_ERR_REPLY, text)  # `bogus` earns err 1
        self.assertIn("< ok status mode=walking", text)
        self.assertIn("< ok stop", text)
        self.assertIn("< err 1 unknown command", text)


    def test_5_sim_port_starts_its_own_virtual_mega(self):
        out = io.StringIO()
        rc = cli.main(["--port", "sim:", "--vbench", os.environ["STRIDER_VBENCH"], "--elf", os.environ["STRIDER_ELF"],
                       "--timeout", "3", "send", "status"], out=out)
        self.assertEqual(rc, cli.EXIT_OK, out.getvalue())
        self.assertTrue(out.getvalue().startswith("ok status mode="), out.getvalue())
        # send waited for the robot to stand up before it sent the line.
        self.assertIn(" state=standing ", out.getvalue())
        self.assertIn(" servos=on ", out.getvalue())

    def test_6_sim_port_sonar_range(self):
        # Open space by default, so that the robot may walk forward; `none`
        # is a sonar without echo (no reading yet, then a sensor fault). The
        # firmware times the echo, so a distance may be a millimetre off.
        for args, sonar, dist in (([], {"ok"}, 2000), (["--sim-range", "350"], {"ok"}, 350),
                                  (["--sim-range", "none"], {"none", "failed"}, None)):
            out = io.StringIO()
            rc = cli.main(["--port", "sim:", "--vbench", os.environ["STRIDER_VBENCH"], "--elf",
                           os.environ["STRIDER_ELF"], "--timeout", "3", *args, "status", "--json"], out=out)
            self.assertEqual(rc, cli.EXIT_OK, out.getvalue())
            st = json.loads(out.getvalue().splitlines()[0])
            self.assertIn(st["sonar"], sonar, st)
            if dist is None:
                self.assertNotIn("dist_mm", st)
            else:
                self.assertAlmostEqual(st["dist_mm"], dist, delta=5, msg=st)

    def test_7_tune_sets_saves_and_keeps_the_parameters(self):
        # A fresh virtual Mega with its own EEPROM file: the tune is saved,
        # the board started again on the same file, the parameters are back.
        with tempfile.TemporaryDirectory() as tmp:
            common = ["--port", "sim:", "--vbench", os.environ["STRIDER_VBENCH"], "--elf", os.environ["STRIDER_ELF"],
                      "--eeprom", os.path.join(tmp, "eeprom.bin"), "--timeout", "3"]
            # A long share down needs its long cycle first; from there (saved,
            # the board started again) a short one goes before its short
            # cycle: robotctl orders them (the other way round one line of
            # each would be refused).
            out = io.StringIO()
            rc = cli.main(common + ["tune", "--gait", "trot", "--step-height", "14.5", "--duty", "0.9", "--cycle", "2.5",
                                    "--swing", "cycloid", "--save", "--json"], out=out)
            self.assertEqual(rc, cli.EXIT_OK, out.getvalue())
            self.assertEqual([json.loads(out.getvalue())[k] for k in ("cycle", "duty")], ["2.50", "0.90"])
            out = io.StringIO()
            rc = cli.main(common + ["tune", "--gait", "trot", "--step-height", "14.5", "--duty", "0.55", "--cycle", "0.6",
                                    "--swing", "cycloid", "--save", "--json"], out=out)
            self.assertEqual(rc, cli.EXIT_OK, out.getvalue())
            tuned = json.loads(out.getvalue())
            self.assertEqual((tuned["gait"], tuned["step_height"], tuned["cycle"], tuned["duty"], tuned["swing"]),
                             ("trot", "14.50", "0.60", "0.55", "cycloid"), tuned)
            out = io.StringIO()
            rc = cli.main(common + ["tune", "--gait", "trot", "--json"], out=out)
            self.assertEqual(rc, cli.EXIT_OK, out.getvalue())
            self.assertEqual(json.loads(out.getvalue()), tuned)
            out = io.StringIO()
            rc = cli.main(common + ["tune", "--step-height", "99"], out=out)
            self.assertEqual(rc, cli.EXIT_ERR_REPLY, out.getvalue())
            self.assertIn("set step_height 99.00: err 25 step_height out of range: 1.00..20.00", out.getvalue())


if __name__ == "__main__":
    unittest.main()
