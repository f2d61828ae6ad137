"""The kinematics sections of docs/results.md: seed 002 tables 4-9, seed 001
body pose ranges and the IK accuracy sweeps, all through the `strider` CLI."""
import math
import random

from results_common import dist, fmt, table


# -- seed 002 tables 4-9 ------------------------------------------------------

# Seed 002 tables 4-9, desired points [cm] (x and z shared; y per leg) and
# the largest per-axis error the paper measured on its robot per table [cm].
S002_X = [7, 8, 9, 10, 11, 12, 13]
S002_Z = [-5, -4, -3, -2, -1, 1, 2]
S002_Y_CORNER = [1, 2, 3, 4, 5, 6, 7]       # tables 4, 6, 7, 9 (legs 1, 3, 4, 6)
S002_Y_MIDDLE = [-3, -2, -1, 1, 2, 3, 4]    # tables 5, 8 (legs 2, 5)
S002_PAPER_MAX_ERR_CM = {4: 0.3, 5: 0.3, 6: 0.3, 7: 0.3, 8: 0.2, 9: 0.4}


def seed002(cli):
    rows, worst = [], {"float": 0.0, "fixed": 0.0}
    all_ok = True
    for t in range(4, 10):
        leg = t - 4  # the paper's leg k is Strider's leg k-1 (test_robot_kinematics.cpp)
        ys = S002_Y_MIDDLE if t in (5, 8) else S002_Y_CORNER
        pts = [(x * 10.0, y * 10.0, z * 10.0) for x, y, z in zip(S002_X, ys, S002_Z)]
        cells = []
        for scalar in ("float", "fixed"):
            res = cli.ik_many("hexapod18", leg, pts, scalar)
            ok = sum(r["status"] == "ok" for r in res)
            all_ok &= ok == len(pts)
            err = 0.0
            for p, r in zip(pts, res):
                if r["joints_deg"] is None:
                    continue
                err = max(err, dist(cli.fk("hexapod18", leg, r["joints_deg"])["foot_mm"], p))
            worst[scalar] = max(worst[scalar], err)
            cells += [f"{ok}/{len(pts)}", fmt(err)]
        rows.append([f"table {t}", f"leg {leg + 1} (Strider leg {leg})", f"{S002_PAPER_MAX_ERR_CM[t] * 10:.0f}"] + cells)
    md = ("Seed 002 tested seven foot positions per leg on its hexapod and measured the foot with a ruler "
          "(tables 4-9). Strider solves the same points (leg frame, cm -> mm) with the hexapod18 model's IK and "
          "checks them with its FK; the error is FK(IK(p)) - p, i.e. the solver alone, without servos or "
          "structure. Errors are from the CLI's printed values (0.0001 deg, 0.0001 mm resolution).\n\n")
    md += table(["table", "paper leg", "paper: worst per-axis error on the robot [mm]", "float: ok", "float: FK(IK(p)) - p [mm]",
                 "fixed: ok", "fixed: FK(IK(p)) - p [mm]"], rows)
    summary = [("002", "tables 4-9: 42 foot positions, position error", "<= 4 mm per axis (measured on the robot)",
                f"{'all 42 solve ok' if all_ok else 'NOT all solve ok'}; IK error <= {fmt(worst['float'])} mm "
                f"float, {fmt(worst['fixed'])} mm fixed (solver only)")]
    return md, summary


# -- seed 001 body pose ranges ------------------------------------------------

def rot_zyx(roll, pitch, yaw):
    cr, sr, cp, sp, cy, sy = (math.cos(math.radians(roll)), math.sin(math.radians(roll)),
                              math.cos(math.radians(pitch)), math.sin(math.radians(pitch)),
                              math.cos(math.radians(yaw)), math.sin(math.radians(yaw)))
    # R = Rz(yaw) Ry(pitch) Rx(roll), seed 001's default order (test_dog12_body_pose.cpp)
    return [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr]]


def moved_foot(p, pose):
    r = rot_zyx(*pose)  # the body turns by R, the feet stay: foot in body = R^T p
    return tuple(sum(r[i][j] * p[i] for i in range(3)) for j in range(3))


S001_RANGE = {"roll": 28, "pitch": 21, "yaw": 21}  # seed 001 table 4 [deg]


def seed001(cli, quick):
    legs = cli.run(["legs", "--robot", "dog12"])
    scan = 60
    poses = []
    for axis in range(3):
        for a in range(-scan, scan + 1):
            pose = [0.0, 0.0, 0.0]
            pose[axis] = float(a)
            poses.append(tuple(pose))
    corners = [(sr * 28.0, sp * 21.0, sy * 21.0) for sr in (-1, 1) for sp in (-1, 1) for sy in (-1, 1)]
    poses += corners
    status = {}  # (pose, scalar) -> all four legs ok
    worst = {"float": 0.0, "fixed": 0.0}
    for leg in legs:
        stand = leg["stand_mm"]
        feet = [moved_foot(stand, p) for p in poses]
        for scalar in ("float", "fixed"):
            res = cli.ik_many("dog12", leg["leg"], feet, scalar, frame="body")
            for pose, foot, r in zip(poses, feet, res):
                key = (pose, scalar)
                status[key] = status.get(key, True) and r["status"] == "ok"
                in_seed = all(abs(v) <= S001_RANGE[n] for v, n in zip(pose, ("roll", "pitch", "yaw")))
                if r["status"] == "ok" and in_seed and (pose in corners or pose.count(0.0) == 2) and not quick \
                        and abs(sum(pose)) % 7 == 0:  # every 7th degree and the corners: FK check
                    got = cli.fk("dog12", leg["leg"], r["joints_deg"], frame="body")["foot_mm"]
                    worst[scalar] = max(worst[scalar], dist(got, foot))
    rows = []
    ranges_ok = True
    for axis, name in enumerate(("roll", "pitch", "yaw")):
        cells = [name, f"+-{S001_RANGE[name]}"]
        for scalar in ("float", "fixed"):
            lo = hi = 0
            while hi < scan and status[(tuple(float(hi + 1) if i == axis else 0.0 for i in range(3)), scalar)]:
                hi += 1
            while -lo < scan and status[(tuple(float(lo - 1) if i == axis else 0.0 for i in range(3)), scalar)]:
                lo -= 1
            ranges_ok &= hi >= S001_RANGE[name] and -lo >= S001_RANGE[name]
            cells.append(f"{lo} .. {hi}" + (" (scan limit)" if hi == scan or -lo == scan else ""))
        rows.append(cells)
    corners_ok = all(status[(c, s)] for c in corners for s in ("float", "fixed"))
    md = ("Seed 001 (table 4) gives its dog's body pose ranges: roll +-28 deg, pitch +-21 deg, yaw +-21 deg. "
          "Strider turns the dog12 body about its centre (R = Rz(yaw) Ry(pitch) Rx(roll)) with all four feet "
          f"held at the standing pose and asks the IK of every leg in the body frame; a pose counts when all "
          f"four legs solve `ok`. Scanned in 1 deg steps, one axis at a time, up to +-{scan} deg:\n\n")
    md += table(["axis", "seed 001 range [deg]", "float: all legs ok [deg]", "fixed: all legs ok [deg]"], rows)
    md += (f"\nThe eight corners (+-28, +-21, +-21 at once): {'all solve ok' if corners_ok else 'NOT all solve'}. "
           + ("" if quick else f"Foot position error of the solved poses (FK of the IK joints, every 7th degree and "
                                f"the corners): {fmt(worst['float'])} mm float, {fmt(worst['fixed'])} mm fixed.") + "\n")
    summary = [("001", "body pose ranges roll / pitch / yaw", "+-28 / +-21 / +-21 deg",
                f"{'covered' if ranges_ok else 'NOT covered'}, corners {'ok' if corners_ok else 'FAIL'}; "
                f"float: {' / '.join(r[2] for r in rows)} deg")]
    return md, summary


# -- accuracy sweeps ----------------------------------------------------------

def accuracy(cli, quick):
    n = 40 if quick else 250
    rows = []
    for robot in (r["name"] for r in cli.run(["robots"])):
        leg = cli.run(["legs", "--robot", robot])[0]
        lim = leg["limits_deg"]
        rng = random.Random(20260)
        qs = [[rng.uniform(lo, hi) for lo, hi in lim] for _ in range(n)]
        pts = [tuple(cli.fk(robot, 0, q)["foot_mm"]) for q in qs]
        res = {s: cli.ik_many(robot, 0, pts, s) for s in ("float", "fixed")}
        cells = [robot, leg["kind"], str(n)]
        for s in ("float", "fixed"):
            errs = []
            for p, r in zip(pts, res[s]):
                if r["status"] == "ok":
                    errs.append(dist(cli.fk(robot, 0, r["joints_deg"])["foot_mm"], p))
            ok = len(errs)
            rms = math.sqrt(sum(e * e for e in errs) / ok) if ok else None
            cells += [f"{ok}", fmt(max(errs) if errs else None), fmt(rms)]
        dq = [max(abs(a - b) for a, b in zip(f["joints_deg"], x["joints_deg"]))
              for f, x in zip(res["float"], res["fixed"]) if f["status"] == "ok" and x["status"] == "ok"]
        cells.append(fmt(max(dq) if dq else None))
        rows.append(cells)
    md = (f"Leg 0 of every model: {n} joint vectors drawn uniformly within the joint limits (fixed seed), their "
          "feet by FK, then IK of those feet in float and in fixed point (Q16.16), and FK of the IK's joints "
          "again. `ok` counts the points the IK solved with status ok (others are limits the IK's own branch "
          "would break, or points at the edge of the workspace); the errors are over those. Values come "
          "through the CLI's printed numbers (0.0001 mm and 0.0001 deg resolution), so float errors at that "
          "level are the print resolution, not the solver.\n\n")
    md += table(["robot", "leg type", "points", "float ok", "float worst [mm]", "float RMS [mm]", "fixed ok",
                 "fixed worst [mm]", "fixed RMS [mm]", "worst fixed - float joint [deg]"], rows)
    return md, []
