#!/usr/bin/env python3
"""Fails when a fixed-point firmware reaches avr-libc's soft-float routines
from anything but its configuration.

The firmware builds its walker and servo map from the model's floats once,
at start-up and when a setting changes (calibration, PWM frequency); every
tick computes in integers. A float that slips into the tick (a library's
float API, a float constant evaluated at run time) costs the cycles of soft
float on every tick: this check walks the ELF's call graph (avr-objdump -d)
and lists every function that can reach a soft-float routine; each must be
one of the configuration functions named below.

  check_float_callers.py --objdump avr-objdump ELF
"""
import argparse
import os
import re
import subprocess
import sys

SOFT_FLOAT = re.compile(r"__(add|sub|mul|div)sf3|__fix(uns)?sfsi|__float(un)?sisf|__(eq|ne|lt|le|gt|ge|un|cmp)sf2|__fp_")

# What may reach soft float: building the walker, its legs and gait
# configuration, and the servo map's constants from the model; the float ->
# scalar conversions they use; the stage's writes, whose slow path (a joint
# the tick map cannot hold, the built-in servos near 400 Hz) rebuilds its
# channel from the model each frame; main, which holds setup() and loop()
# once inlined and may call these, but no soft-float routine directly.
CONFIGURATION = re.compile(
    r"configure|build_legs|make_leg\(|mount_of\(|limits_of<|leg_solver_(of|count|index)\(|"
    r"make_joint_channel<|fit_legs\(|apply_pwm<|write_legs(_slowly)?<|from_double\(|deg_to_rad<|"
    r"Vec3<strider::Fixed>::from<float>|avoid_clear_mm\(")


def call_graph(dump):
    """function -> the functions it calls or jumps to."""
    calls, func = {}, None
    for line in dump.splitlines():
        m = re.match(r"^[0-9a-f]+ <(.*)>:$", line)
        if m:
            func = m.group(1)
            calls.setdefault(func, set())
            continue
        m = re.search(r"\t(r?call|r?jmp)\t.*; 0x[0-9a-f]+ <(.*)>$", line)
        if func and m:
            target = re.sub(r"\+0x[0-9a-f]+$", "", m.group(2))
            if target != func:
                calls[func].add(target)
    return calls


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--objdump", default="avr-objdump")
    ap.add_argument("elf")
    a = ap.parse_args()
    if not os.path.exists(a.elf):
        print(f"skipped: no {a.elf} (its build was skipped)")
        return 0
    dump = subprocess.run([a.objdump, "-d", "-C", a.elf], capture_output=True, text=True, check=True).stdout
    calls = call_graph(dump)
    reach = {f for f in calls if SOFT_FLOAT.match(f)}
    grew = True
    while grew:
        grew = False
        for f, targets in calls.items():
            if f not in reach and targets & reach:
                reach.add(f)
                grew = True
    bad = []
    for f in sorted(reach):
        if f.startswith("__"):
            continue  # the library's own routines
        if f == "main":
            direct = sorted(t for t in calls[f] if SOFT_FLOAT.match(t) or re.search(r"from_double\(|deg_to_rad<", t))
            if direct:
                bad.append(f"main calls {', '.join(direct)}")
        elif not CONFIGURATION.search(f):
            bad.append(f)
    if bad:
        print(f"{a.elf}: soft float reached outside the configuration:\n  " + "\n  ".join(bad))
        return 1
    users = sum(1 for f in reach if not f.startswith("__"))
    print(f"{a.elf}: soft float only in the configuration ({users} functions)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
