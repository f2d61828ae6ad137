"""robotctl: command line client for a Strider robot (docs/robotctl.md).

Exit status: 0 success, 1 the robot answered err, 2 bad usage or script,
3 no reply in time, 4 the port could not be opened or broke.
"""
import argparse
import json
import os
import sys
import time
from typing import Dict, List, Optional

from . import __version__
from .link import RESETTING_PORT, Link, LinkError, ReplyTimeout, open_port
from .protocol import RC_BYTES, check_line, parse_status, status_summary, unescape
from .script import ScriptError, parse_script, play

EXIT_OK, EXIT_ERR_REPLY, EXIT_USAGE, EXIT_TIMEOUT, EXIT_LINK = 0, 1, 2, 3, 4


def _sim_range(text: str) -> str:
    from .sim import parse_range
    try:
        return parse_range(text)
    except ValueError as e:
        raise argparse.ArgumentTypeError(str(e)) from e


def add_common(ap: argparse.ArgumentParser, top: bool) -> None:
    """The link options; also accepted after the command (`robotctl send
    --port P ...`), where they must not reset what was given before it."""
    def d(value):
        return value if top else argparse.SUPPRESS

    ap.add_argument("--port", "-p", default=d(os.environ.get("ROBOTCTL_PORT")), help="serial port (see below)")
    ap.add_argument("--baud", "-b", type=int, default=d(9600), help="baud rate (HC-05: 9600; USB: 115200)")
    ap.add_argument("--timeout", type=float, default=d(2.0), help="seconds to wait for a reply (default 2)")
    ap.add_argument("--boot-wait", type=float, default=d(None),
                    help="seconds to wait for the boot line after opening (default: 3 on USB ports that "
                         "reset the board, else 0)")
    ap.add_argument("--quiet", "-q", action="store_true", default=d(False), help="do not print info notices")
    ap.add_argument("--plain", action="store_true", default=d(False),
                    help="send plain text lines, as a phone app does (default: checked lines, $text*hhhh)")
    ap.add_argument("--vbench", default=d(None), help="sim: the vbench executable (default: build dir, $STRIDER_VBENCH, PATH)")
    ap.add_argument("--elf", default=d(None), help="sim: the firmware ELF (default: the model's in the build dir, $STRIDER_ELF)")
    ap.add_argument("--eeprom", default=d(None), help="sim: EEPROM image file kept between runs")
    ap.add_argument("--build-dir", default=d(None), help="sim: CMake build directory (default $STRIDER_BUILD_DIR or out/build)")
    ap.add_argument("--sim-range", default=d(None), metavar="MM|none", type=_sim_range,
                    help="sim: the virtual sonar's echo distance in mm, or none for no echo (a sensor fault); "
                         "default 2000, open space")


def build_parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(
        prog="robotctl", description="Talk to a Strider robot over its serial link.",
        epilog="PORT: a device (/dev/ttyACM0, /dev/rfcomm0), the pty printed by `vbench --pty`, a pyserial URL "
               "(socket://host:port), or sim:[MODEL|ELF] to start the virtual Mega. $ROBOTCTL_PORT is the default.")
    add_common(ap, top=True)
    ap.add_argument("--version", action="version", version=f"robotctl {__version__}")
    sub = ap.add_subparsers(dest="cmd", metavar="COMMAND")

    p = sub.add_parser("send", help="send text lines, print one reply each")
    p.add_argument("lines", nargs="+", metavar="LINE", help="a text command, e.g. 'walk 100'")
    p.add_argument("--rc", action="store_true", help="send the arguments as RC bytes (no line end, no reply)")
    p.add_argument("--raw", action="store_true", help="send as is with \\n \\r escapes; wait one reply per line")
    p.add_argument("--stand-wait", type=float, default=15.0, metavar="S",
                   help="after a boot (sim: ports, a USB port that resets the board), wait up to S seconds "
                        "for the robot to stand before sending (default 15; 0: send at once)")

    p = sub.add_parser("status", help="ask for the status line and print its fields")
    p.add_argument("--json", action="store_true", help="one JSON object per status")
    p.add_argument("--watch", type=float, metavar="S", help="repeat every S seconds until Ctrl-C")
    p.add_argument("--count", type=int, default=0, help="with --watch: stop after N statuses")

    p = sub.add_parser("drive", help="drive from the keyboard (curses)")
    p.add_argument("--hold", action="store_true", help="move only while a key is held (stop on release)")
    p.add_argument("--repeat", type=float, default=0.25, help="seconds between repeated motion bytes")
    p.add_argument("--release", type=float, default=0.6, help="hold mode: seconds without a key that mean release")
    p.add_argument("--status-period", type=float, default=1.0, help="seconds between status refreshes (0 = off)")

    p = sub.add_parser("tune", help="show or set the live gait parameters of a gait (set/get, docs/protocol.md)")
    p.add_argument("--gait", help="switch to this gait first (each gait has its own parameters)")
    p.add_argument("--step-height", type=float, metavar="MM", help="swing apex [mm]")
    p.add_argument("--step-length", type=float, metavar="MM", help="preferred stride [mm]")
    p.add_argument("--cycle", type=float, metavar="S", help="cycle time at low speed [s]")
    p.add_argument("--duty", type=float, metavar="D", help="share of the cycle a foot is down, 0..1")
    p.add_argument("--swing", metavar="SHAPE", help="swing path: rectangle semicircle ellipse cycloid parabola bezier")
    p.add_argument("--height", type=float, metavar="MM", help="body height [mm]")
    p.add_argument("--save", action="store_true", help="keep them in EEPROM (with the other settings)")
    p.add_argument("--json", action="store_true", help="print the parameters as one JSON object")

    p = sub.add_parser("play", help="play a timed script (see docs/robotctl.md)")
    p.add_argument("script", help="script file, - for stdin")
    p.add_argument("--check", action="store_true", help="only parse the script, print its steps")

    p = sub.add_parser("monitor", help="print every line received; lines typed on stdin are sent")
    p.add_argument("--duration", type=float, default=0.0, help="stop after S seconds (default: until Ctrl-C/EOF)")
    p.add_argument("--no-stdin", action="store_true", help="only listen")
    for p in sub.choices.values():
        add_common(p, top=False)
    return ap


class Drive:
    """An open link, and the virtual Mega behind it for sim: ports."""

    def __init__(self, args, out):
        self.args, self.out, self.vm = args, out, None
        self.booted = False  # the board booted as the port opened (sim:, a resetting USB port)
        try:
            self._open(args.port)
        except BaseException:
            if self.vm is not None:  # never leave a virtual Mega running
                self.vm.stop()
            raise

    def _open(self, port):
        args = self.args
        if port.startswith("sim:"):
            port = self._start_sim(port[4:])
        self.link = Link(open_port(port, args.baud), checked=not args.plain)
        self.link.on_event = self._on_event
        wait = args.boot_wait
        if self.vm is not None:
            # The virtual board boots as vbench starts: wait for its boot
            # line, then for an answer.
            if not self.link.wait_ready(wait if wait is not None else 30.0):
                raise LinkError(f"the virtual Mega did not answer: {' | '.join(self.vm.output)}")
            self.booted = True
            return
        if wait is None:
            wait = 3.0 if RESETTING_PORT.match(port) else 0.0
        if wait > 0:
            self.booted = self.link.wait_for(r"^info strider .*ready", wait) is not None

    def _start_sim(self, spec):
        from .sim import DEFAULT_RANGE_MM, VirtualMega, build_dir, find_elf, find_vbench
        bd = build_dir(self.args.build_dir)
        vbench = find_vbench(self.args.vbench, bd)
        elf = find_elf(spec, self.args.elf, bd)
        if not vbench:
            raise LinkError("sim: no vbench executable (build tools/vbench, or give --vbench)")
        if not elf:
            raise LinkError(f"sim: no firmware ELF for '{spec or 'sprawl8'}' (build it, or give --elf)")
        self.vm = VirtualMega(vbench, elf, self.args.eeprom, range_mm=self.args.sim_range or DEFAULT_RANGE_MM)
        return self.vm.start()

    def _on_event(self, ev):
        if ev.kind == "info" and not self.args.quiet and self.args.cmd not in ("drive", "monitor"):
            print(ev.line, file=sys.stderr)
        if ev.kind == "damaged" and self.args.cmd not in ("drive", "monitor"):
            print(f"robotctl: damaged line (its check failed): {ev.line}", file=sys.stderr)

    def close(self):
        self.link.close()
        if self.vm is not None:
            self.vm.stop()


def cmd_send(s: Drive, a, out) -> int:
    rc = EXIT_OK
    # A board that just booted switches its legs on one at a time and stands
    # up: what is sent meanwhile would meet a robot still rising.
    if s.booted and a.stand_wait > 0 and not s.link.wait_standing(a.stand_wait):
        print(f"robotctl: the robot did not stand up within {a.stand_wait:g} s; sending anyway", file=sys.stderr)
    if a.rc:
        bad = [c for c in "".join(a.lines) if c not in RC_BYTES]
        if bad:
            print(f"robotctl: not RC bytes: {''.join(bad)!r} (allowed: {RC_BYTES})", file=sys.stderr)
            return EXIT_USAGE
        for chunk in a.lines:
            s.link.write_rc(chunk)
        return EXIT_OK
    for line in a.lines:
        reqs = s.link.write_raw(unescape(line), check=False) if a.raw else [s.link.write_line(line)]
        if not a.raw:
            why = check_line(line, checked=s.link.checked and not line.startswith("$"))
            if why:
                print(f"robotctl: warning: {line!r}: {why}", file=sys.stderr)
        for req in reqs:
            try:
                r = s.link.wait_reply(req, a.timeout)
            except ReplyTimeout as e:
                print(f"robotctl: {e}", file=sys.stderr)
                return EXIT_TIMEOUT
            print(r.line, file=out)
            if not r.ok:
                rc = EXIT_ERR_REPLY
    return rc


def cmd_status(s: Drive, a, out) -> int:
    n = 0
    while True:
        try:
            r = s.link.command("status", a.timeout)
        except ReplyTimeout as e:
            print(f"robotctl: {e}", file=sys.stderr)
            return EXIT_TIMEOUT
        if not r.ok:
            print(r.line, file=out)
            return EXIT_ERR_REPLY
        st = parse_status(r)
        if a.json:
            print(json.dumps(st), file=out)
        elif a.watch:
            print(f"{time.strftime('%H:%M:%S')}  {status_summary(st)}", file=out)
        else:
            width = max(len(k) for k in st) if st else 0
            for k, v in st.items():
                print(f"{k:<{width}}  {v}", file=out)
        out.flush()
        n += 1
        if not a.watch or (a.count and n >= a.count):
            return EXIT_OK
        end = s.link.clock() + a.watch
        while s.link.clock() < end:
            s.link.poll(end - s.link.clock())


def tune_lines(a, duty_now: Optional[float] = None) -> List[str]:
    """The `set` and `height` lines of `robotctl tune`'s options, in the
    order the robot needs them: the parameters, then the height. The robot
    checks the cycle against the duty and the duty against the cycle: a duty
    shorter than `duty_now` (the one walked) goes before the cycle, a longer
    one after it."""
    names = ["step_height", "step_length", "cycle", "duty"]
    if a.duty is not None and duty_now is not None and a.duty < duty_now:
        names = ["step_height", "step_length", "duty", "cycle"]
    lines = [f"set {name} {getattr(a, name):.2f}" for name in names if getattr(a, name) is not None]
    if a.swing:
        lines.append(f"set swing {a.swing}")
    if a.height is not None:
        lines.append(f"height {a.height:.1f}")
    return lines


def reply_fields(line: str) -> Dict[str, str]:
    """`ok get gait=trot cycle=0.80 ...` -> {"gait": "trot", "cycle": "0.80", ...}."""
    return dict(kv.split("=", 1) for kv in line.split()[2:] if "=" in kv)


def cmd_tune(s: Drive, a, out) -> int:
    if s.booted and not s.link.wait_standing(15.0):
        print("robotctl: the robot did not stand up within 15 s; sending anyway", file=sys.stderr)

    def send(line):  # the reply, or None after printing a refusal
        r = s.link.command(line, a.timeout)
        if not r.ok:
            print(f"{line}: {r.line}", file=out)
            return None
        return r

    try:
        if a.gait and send(f"gait {a.gait}") is None:
            return EXIT_ERR_REPLY
        duty_now = None
        if a.cycle is not None and a.duty is not None:  # their order depends on the duty walked now
            now = send("get")
            if now is None:
                return EXIT_ERR_REPLY
            duty_now = float(reply_fields(now.line).get("duty", "nan"))
        for line in tune_lines(a, duty_now) + (["save"] if a.save else []):
            if send(line) is None:
                return EXIT_ERR_REPLY
        r = s.link.command("get", a.timeout)
    except ReplyTimeout as e:
        print(f"robotctl: {e}", file=sys.stderr)
        return EXIT_TIMEOUT
    if not r.ok:
        print(r.line, file=out)
        return EXIT_ERR_REPLY
    fields = reply_fields(r.line)
    if a.json:
        print(json.dumps(fields), file=out)
    else:
        width = max(len(k) for k in fields) if fields else 0
        for k, v in fields.items():
            print(f"{k:<{width}}  {v}", file=out)
    return EXIT_OK


def cmd_play(s: Optional[Drive], a, out, steps) -> int:
    res = play(s.link, steps, lambda t: (print(t, file=out), out.flush()), a.timeout)
    print(f"# {res.sent} lines, {res.errors} err replies, {res.timeouts} timeouts", file=out)
    if res.timeouts:
        return EXIT_TIMEOUT
    return EXIT_ERR_REPLY if res.errors else EXIT_OK


def cmd_monitor(s: Drive, a, out) -> int:
    import select
    start = s.link.clock()
    use_stdin = not a.no_stdin
    while not a.duration or s.link.clock() - start < a.duration:
        for ev in s.link.poll(0.05):
            tag = " (late)" if ev.late else " (damaged: its check failed)" if ev.kind == "damaged" else ""
            print(f"{ev.time - start:8.3f} < {ev.line}{tag}", file=out)
        if use_stdin:
            ready, _, _ = select.select([sys.stdin], [], [], 0)
            if ready:
                line = sys.stdin.readline()
                if not line:
                    use_stdin = False
                    if not a.duration:
                        # Input ended: collect the last replies, then stop.
                        end = s.link.clock() + a.timeout
                        while s.link.waiting and s.link.clock() < end:
                            for ev in s.link.poll(end - s.link.clock()):
                                print(f"{ev.time - start:8.3f} < {ev.line}", file=out)
                        break
                else:
                    line = line.rstrip("\r\n")
                    s.link.write_line(line)  # an RC letter on its own line is answered `ok rc X`
                    print(f"{s.link.clock() - start:8.3f} > {line}", file=out)
        out.flush()
    return EXIT_OK


def cmd_drive(s: Drive, a, out) -> int:
    from .drive import DriveState, run_curses
    if not sys.stdin.isatty():
        print("robotctl: drive needs a terminal", file=sys.stderr)
        return EXIT_USAGE
    ds = DriveState(s.link, latch=not a.hold, repeat_s=a.repeat, release_s=a.release,
                      status_period_s=a.status_period)
    run_curses(ds, f"robotctl drive  {a.port}")
    return EXIT_OK


def main(argv: Optional[List[str]] = None, out=None) -> int:
    out = out or sys.stdout
    ap = build_parser()
    a = ap.parse_args(argv)
    if not a.cmd:
        ap.print_help(sys.stderr)
        return EXIT_USAGE
    steps = None
    if a.cmd == "play":
        try:
            if a.script == "-":
                text = sys.stdin.read()
            else:
                with open(a.script) as f:
                    text = f.read()
            steps = parse_script(text)
        except (OSError, ScriptError) as e:
            print(f"robotctl: {e}", file=sys.stderr)
            return EXIT_USAGE
        if a.check:
            for st in steps:
                when = f"at {st.at:g}" if st.at is not None else (f"+{st.after:g}" if st.after is not None else "next")
                print(f"line {st.lineno}: {when} {st.kind} {st.payload!r}", file=out)
            return EXIT_OK
    if not a.port:
        print("robotctl: no port: give --port (or set ROBOTCTL_PORT)", file=sys.stderr)
        return EXIT_USAGE
    try:
        s = Drive(a, out)
    except LinkError as e:
        print(f"robotctl: {e}", file=sys.stderr)
        return EXIT_LINK
    try:
        if a.cmd == "send":
            return cmd_send(s, a, out)
        if a.cmd == "status":
            return cmd_status(s, a, out)
        if a.cmd == "play":
            return cmd_play(s, a, out, steps)
        if a.cmd == "tune":
            return cmd_tune(s, a, out)
        if a.cmd == "monitor":
            return cmd_monitor(s, a, out)
        return cmd_drive(s, a, out)
    except KeyboardInterrupt:
        return EXIT_OK
    except LinkError as e:
        print(f"robotctl: {e}", file=sys.stderr)
        return EXIT_LINK
    finally:
        s.close()


if __name__ == "__main__":
    sys.exit(main())
