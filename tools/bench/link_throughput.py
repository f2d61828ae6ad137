#!/usr/bin/env python3
"""The command link under load: lines answered per second, per port and baud
rate, measured on the firmware on the virtual Mega with vbench's link floods
(docs/reliability.md, "The command link under load").

For each firmware, port (USB 115200, Bluetooth 9600 and 115200) and line, the
robot walks (deadman off) while vbench floods the port with that line at a
rate, for a few simulated seconds; the script counts the replies that come
while the flood lasts and 0.3 s after: ok, err 10 (bytes lost: the line was
damaged and dropped) and other errors. The rates climb until the robot no
longer answers every line ok in that time; the last one that it did is the
sustained rate. "max" is a flood back to back at the baud rate.

    tools/bench/link_throughput.py --vbench out/build/tools/vbench/vbench \\
        --firmware-dir out/build/src [--models sprawl8 hexapod18] [--seconds 4]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

LINE = re.compile(r"^(\d+\.\d+) uart(\d): (.*)$")
FLOOD = re.compile(r"^# flood uart(\d): (\d+) units, (\d+) bytes")
RATES = (1, 2, 3, 5, 10, 20, 40, 60, 100, 150, 200, 300, 400, 500, 600, 800, 1000)
LINES = ("speed 50", "status")
PORTS = ((0, 115200), (1, 9600), (1, 115200))
WALK_AT = 3.0    # after the soft start
FLOOD_AT = 4.0
SLACK_S = 0.3    # replies counted after the flood ends


def run(vbench, elf, script, duration, eeprom=None):
    with tempfile.NamedTemporaryFile("w", suffix=".vbs", delete=False) as f:
        f.write(script)
        path = f.name
    try:
        cmd = [vbench, "--elf", elf, "--script", path, "--duration", f"{duration:g}", "--log"]
        if eeprom:
            cmd += ["--eeprom", eeprom]
        out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    finally:
        os.unlink(path)
    return out.splitlines()


def bluetooth_115200_eeprom(vbench, elf, path):
    """An EEPROM image whose settings put the HC-05 link at 115200 baud."""
    if os.path.exists(path):
        os.unlink(path)
    run(vbench, elf, "at 3 send baud 115200\\n\nat 3.5 send save\\n\n", 4.5, path)


def measure(vbench, elf, port, baud, text, rate, seconds, eeprom):
    send = "send0" if port == 0 else "send"
    flood = "flood0" if port == 0 else "flood"
    script = (f"at 2.5 range 2000\n"
              f"at {WALK_AT} {send} $deadman off*cb77\\n\n"  # a checked line (docs/protocol.md)
              f"at {WALK_AT + 0.2} {send} walk 60\\n\n"
              f"at {FLOOD_AT} {flood} {rate} {seconds:g} {text}\\n\n")
    end = FLOOD_AT + seconds
    # Replies count while the flood lasts and SLACK_S after: a sender at a
    # rate the robot only seems to keep up with for a few seconds, because
    # its receive buffer holds the backlog, does not pass.
    out = run(vbench, elf, script, end + SLACK_S + 0.2, eeprom)
    ok = lost = other = units = 0
    resets = 0
    reply_bytes = []
    for line in out:
        m = LINE.match(line)
        if m and int(m.group(2)) == port and FLOOD_AT <= float(m.group(1)) <= end + SLACK_S:
            reply = m.group(3)
            if reply.startswith("ok"):
                ok += 1
                reply_bytes.append(len(reply) + 2)
            elif reply.startswith("err 10 "):
                lost += 1
            elif reply.startswith("err"):
                other += 1
        f = FLOOD.match(line)
        if f and int(f.group(1)) == port:
            units = int(f.group(2))
        if "reset (" in line:
            resets += 1
    return {"reply_bytes": max(reply_bytes) if reply_bytes else 0, "sent": units / seconds, "ok": ok / seconds, "lost": lost / seconds, "other": other / seconds,
            "all_ok": ok == units and lost == 0 and other == 0 and resets == 0, "resets": resets}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--vbench", required=True)
    ap.add_argument("--firmware-dir", required=True)
    ap.add_argument("--models", nargs="+", default=["sprawl8", "hexapod18"])
    ap.add_argument("--seconds", type=float, default=4.0, help="flood length [simulated s]")
    a = ap.parse_args()
    print("| model | port | baud | line (reply bytes) | sustained: every line answered ok [lines/s] "
          "| back to back: sent / ok / err 10 / other err [lines/s] |")
    print("|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for model in a.models:
            elf = os.path.join(a.firmware_dir, f"strider_firmware_{model}.elf")
            fast = os.path.join(tmp, f"{model}_bt115200.eeprom")
            bluetooth_115200_eeprom(a.vbench, elf, fast)
            for port, baud in PORTS:
                for text in LINES:
                    eeprom = None
                    if port == 1 and baud == 115200:
                        eeprom = os.path.join(tmp, "run.eeprom")
                        with open(fast, "rb") as src, open(eeprom, "wb") as dst:
                            dst.write(src.read())
                    sustained, reply = 0, 0
                    for rate in RATES:
                        r = measure(a.vbench, elf, port, baud, text, rate, a.seconds, eeprom)
                        if not r["all_ok"] or r["sent"] < 0.9 * rate:
                            break
                        sustained, reply = rate, r["reply_bytes"]
                    r = measure(a.vbench, elf, port, baud, text, "max", a.seconds, eeprom)
                    reply = reply or r["reply_bytes"]
                    print(f"| {model} | {'USB' if port == 0 else 'Bluetooth'} | {baud} | `{text}` ({reply}) "
                          f"| {sustained} | {r['sent']:.0f} / {r['ok']:.0f} / {r['lost']:.0f} / {r['other']:.0f}"
                          f"{' RESET' if r['resets'] else ''} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
