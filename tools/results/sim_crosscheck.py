#!/usr/bin/env python3
"""Sanity check of strider-sim against pybullet: the joint targets a
strider-sim run sent to its servos (trace.csv, one row per 20 ms tick) are
replayed open loop on the same robot built independently in pybullet, and
the two bodies' paths are compared (docs/results.md).

Same sizes, masses, friction and servo limits as strider-sim's world (from
the model through the `strider` CLI, scene.json and the servo table of
lib/strider/robots/servo_parts.h), but pybullet's own contact model, motor
and solver; no servo dead band or PWM quantisation. Sprawl legs only (the
seed 000 robot), which is what the check is run on.


  DIR: a strider-sim --out folder (trace.csv, scene.json, metrics.json)
Exit 77 when pybullet is not installed.
"""
import argparse
import csv
import json
import math
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
KG_CM_TO_NM = 0.0980665
LINK_DENSITY_KG_MM = 0.1e-3   # strider-sim's WorldConfig: 0.1 g per mm of link
FOOT_FRICTION, BODY_FRICTION = 0.8, 0.4
STEP_S = 0.002
# MuJoCo integrates the servo's stiffness explicitly: a stiff servo on a
# 7 g link rings at about 200 Hz, so its step must be much finer.
MJ_STEP_S = 0.0005
# Joint axes in the leg frame at the zero configuration, links along +x
# (tools/sim/leg_geometry.cpp): the first joint yaws (sprawl, seed 000) or
# pitches (planar, seed 003); the knee pitches, a positive angle lifting.
FIRST_AXIS = {"sprawl": [0, 0, 1], "planar": [0, -1, 0]}


def servo_table():
    """name -> (torque [N m], speed [rad/s], mass [kg]) from servo_parts.h."""
    text = (ROOT / "lib" / "strider" / "robots" / "servo_parts.h").read_text()
    out = {}
    for m in re.finditer(r'ServoSpec\{"(\w+)",\s*([\d.]+)f?,\s*(\d+),\s*(\d+),\s*([\d.]+)f?,\s*([\d.]+)f?,\s*([\d.]+)f?\}',
                         text):
        name, torque, s60, mass = m.group(1), float(m.group(5)), float(m.group(6)), float(m.group(7))
        out[name] = (torque * KG_CM_TO_NM, math.radians(60.0) / s60, mass * 1e-3)
    return out


def body_mass(robot, dims):
    """The model's total mass [kg]: the body line {L, W, H, M} of its header."""
    text = (ROOT / "lib" / "strider" / "robots" / f"{robot}.h").read_text()
    pat = r"\{\s*" + r"f?,\s*".join(f"{d:g}\\.?0*" for d in dims) + r"f?,\s*([\d.]+)f?\s*\}"
    m = re.search(pat, text)
    if not m:
        raise RuntimeError(f"no body {{{dims}, mass}} in {robot}.h")
    return float(m.group(1))


def foot_radius_mm(robot):
    """foot_radius_mm of the robot's kGaitParams entry (gait_params.h)."""
    text = (ROOT / "lib" / "strider" / "gait" / "gait_params.h").read_text()
    m = re.search(r'\{"' + re.escape(robot) + r'",\s*"\w+",\s*SwingShape::\w+,' + r"\s*([\d.]+)f?," * 5, text)
    if not m:
        raise RuntimeError(f"no kGaitParams entry for {robot} in gait_params.h")
    return float(m.group(5))  # step height, step length, cycle, stance depth, foot radius


def cli(strider, *args):
    p = subprocess.run([strider, *args], capture_output=True, text=True, check=True)
    return [json.loads(line) for line in p.stdout.splitlines()]


def robot_spec(run_dir, strider):
    """The robot of a strider-sim run, as strider-sim's world builds it: sizes
    [m], masses [kg], servo limits, and the trace rows."""
    scene = json.loads((run_dir / "scene.json").read_text())
    robot = scene["robot"]
    legs = cli(strider, "legs", "--robot", robot)
    kind = legs[0]["kind"]
    if kind not in FIRST_AXIS:
        raise RuntimeError(f"{robot}: only 2-DOF sprawl and planar legs are built here, not {kind}")
    # Link lengths from the leg's own FK: t = (0, 0) stretches both links
    # along x; t2 = 90 deg puts the shank straight up.
    x0 = cli(strider, "fk", "--robot", robot, "--leg", "0", "--joints", "0,0")[0]["foot_mm"][0]
    up = cli(strider, "fk", "--robot", robot, "--leg", "0", "--joints", "0,90")[0]["foot_mm"]
    l1, l2 = up[0], up[2]
    assert abs(l1 + l2 - x0) < 1e-3, "2-link FK: l1 + l2 must be the stretched reach"
    servos = servo_table()
    total = body_mass(robot, scene["body_mm"])
    foot_r = max(3.0, foot_radius_mm(robot)) * 1e-3  # as strider-sim's world: at least 3 mm
    spec = {"robot": robot, "kind": kind, "body": [v * 1e-3 for v in scene["body_mm"]], "l1": l1 * 1e-3,
            "l2": l2 * 1e-3, "foot_r": foot_r, "link_r": max(2e-3, 0.5 * foot_r), "legs": [],
            "rows": list(csv.DictReader(open(run_dir / "trace.csv")))}
    legs_mass = 0.0
    for i, leg in enumerate(legs):
        s_knee = servos[leg["servos"][1]]
        m_thigh = LINK_DENSITY_KG_MM * l1 + s_knee[2]  # the knee servo rides at the thigh's end
        m_shank = LINK_DENSITY_KG_MM * l2
        legs_mass += m_thigh + m_shank
        spec["legs"].append({
            "hip": [h * 1e-3 for h in scene["hips_mm"][i]], "yaw": math.radians(leg["mount_yaw_deg"]),
            "m_thigh": m_thigh, "m_shank": m_shank, "knee_servo_kg": s_knee[2],
            "c_thigh": (LINK_DENSITY_KG_MM * l1 * l1 * 0.5e-3 + s_knee[2] * l1 * 1e-3) / m_thigh,
            "motors": [servos[leg["servos"][0]], s_knee]})
    spec["body_mass"] = max(0.1 * total, total - legs_mass)
    return spec


def tilt_deg(roll, pitch):
    return math.degrees(math.acos(max(-1.0, min(1.0, math.cos(roll) * math.cos(pitch)))))


def replay_pybullet(spec):
    import pybullet as pb

    l1, l2, foot_r, link_r = spec["l1"], spec["l2"], spec["foot_r"], spec["link_r"]
    rows = spec["rows"]
    n_legs = len(spec["legs"])
    pb.connect(pb.DIRECT)
    pb.setGravity(0, 0, -9.81)
    pb.setPhysicsEngineParameter(fixedTimeStep=STEP_S, numSolverIterations=50)
    plane = pb.createCollisionShape(pb.GEOM_PLANE)
    ground = pb.createMultiBody(0, plane)
    pb.changeDynamics(ground, -1, lateralFriction=1.0)

    masses, col, vis, pos, orn, inertial_pos, parents, joint_types, axes = [], [], [], [], [], [], [], [], []
    motor = []
    along_x = pb.getQuaternionFromEuler([0, math.pi / 2, 0])
    for leg in spec["legs"]:
        thigh = pb.createCollisionShape(pb.GEOM_CAPSULE, radius=link_r, height=l1,
                                        collisionFramePosition=[l1 / 2, 0, 0], collisionFrameOrientation=along_x)
        # Shank: a capsule up to the foot sphere's centre, and the foot
        # sphere whose bottom is the shank's tip (as strider-sim builds it).
        seg = l2 - foot_r
        shank = pb.createCollisionShapeArray(
            shapeTypes=[pb.GEOM_CAPSULE, pb.GEOM_SPHERE], radii=[link_r, foot_r], lengths=[seg, 0],
            collisionFramePositions=[[seg / 2, 0, 0], [seg, 0, 0]], collisionFrameOrientations=[along_x, [0, 0, 0, 1]])
        # Thigh: first joint at the hip; shank: knee at l1 (axis -y).
        base_index = len(masses)
        masses += [leg["m_thigh"], leg["m_shank"]]
        col += [thigh, shank]
        vis += [-1, -1]
        pos += [leg["hip"], [l1, 0, 0]]
        orn += [pb.getQuaternionFromEuler([0, 0, leg["yaw"]]), [0, 0, 0, 1]]
        inertial_pos += [[leg["c_thigh"], 0, 0], [l2 / 2, 0, 0]]
        parents += [0, base_index + 1]
        joint_types += [pb.JOINT_REVOLUTE, pb.JOINT_REVOLUTE]
        axes += [FIRST_AXIS[spec["kind"]], [0, -1, 0]]
        motor += leg["motors"]
    bx, by, bz = spec["body"]
    base = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=[bx / 2, by / 2, bz / 2])
    r0 = rows[0]
    robot_id = pb.createMultiBody(
        baseMass=spec["body_mass"], baseCollisionShapeIndex=base, basePosition=[0, 0, float(r0["z_mm"]) * 1e-3],
        linkMasses=masses, linkCollisionShapeIndices=col, linkVisualShapeIndices=vis, linkPositions=pos,
        linkOrientations=orn, linkInertialFramePositions=inertial_pos,
        linkInertialFrameOrientations=[[0, 0, 0, 1]] * len(masses), linkParentIndices=parents,
        linkJointTypes=joint_types, linkJointAxis=axes)
    for j in range(len(masses)):
        pb.changeDynamics(robot_id, j, lateralFriction=FOOT_FRICTION if j % 2 else BODY_FRICTION)
        pb.setJointMotorControl2(robot_id, j, pb.VELOCITY_CONTROL, force=0)
    pb.changeDynamics(robot_id, -1, lateralFriction=BODY_FRICTION)
    for i in range(n_legs):
        for j in range(2):
            pb.resetJointState(robot_id, 2 * i + j, math.radians(float(r0[f"q_{i}_{j}"])))

    ticks = int(round(0.02 / STEP_S))
    path = []
    for k, row in enumerate(rows):
        for i in range(n_legs):
            for j in range(2):
                torque, speed, _ = motor[2 * i + j]
                pb.setJointMotorControl2(robot_id, 2 * i + j, pb.POSITION_CONTROL,
                                         targetPosition=math.radians(float(row[f"target_{i}_{j}"])),
                                         force=torque, maxVelocity=speed, positionGain=50 * STEP_S, velocityGain=1.0)
        p, q = pb.getBasePositionAndOrientation(robot_id)
        roll, pitch, yaw = pb.getEulerFromQuaternion(q)
        path.append((float(row["t"]), p[0] * 1e3, p[1] * 1e3, math.degrees(yaw), tilt_deg(roll, pitch)))
        if k + 1 < len(rows):
            for _ in range(ticks):
                pb.stepSimulation()
    pb.disconnect()
    return path


def mjcf(spec):
    """The robot as MuJoCo XML: the same bodies; each servo a position
    actuator that saturates at the stall torque, with damping torque/speed
    so that the unloaded joint cannot outrun the servo's no-load speed."""
    l1, l2, fr, lr = spec["l1"], spec["l2"], spec["foot_r"], spec["link_r"]
    bx, by, bz = spec["body"]
    z0 = float(spec["rows"][0]["z_mm"]) * 1e-3
    axis0 = " ".join(str(v) for v in FIRST_AXIS[spec["kind"]])
    legs_xml, acts = [], []
    for i, leg in enumerate(spec["legs"]):
        m_link1 = leg["m_thigh"] - leg["knee_servo_kg"]
        legs_xml.append(f"""
      <body name="thigh{i}" pos="{leg['hip'][0]} {leg['hip'][1]} {leg['hip'][2]}" euler="0 0 {leg['yaw']}">
        <joint name="j{i}_0" type="hinge" axis="{axis0}"/>
        <geom type="capsule" fromto="0 0 0 {l1} 0 0" size="{lr}" mass="{m_link1}" friction="{BODY_FRICTION}"/>
        <geom type="sphere" pos="{l1} 0 0" size="{lr}" mass="{leg['knee_servo_kg']}" contype="0" conaffinity="0"/>
        <body name="shank{i}" pos="{l1} 0 0">
          <joint name="j{i}_1" type="hinge" axis="0 -1 0"/>
          <geom type="capsule" fromto="0 0 0 {l2 - fr} 0 0" size="{lr}" mass="{leg['m_shank'] * 0.5}" friction="{BODY_FRICTION}"/>
          <geom type="sphere" pos="{l2 - fr} 0 0" size="{fr}" mass="{leg['m_shank'] * 0.5}" friction="{FOOT_FRICTION}"/>
        </body>
      </body>""")
        for j in range(2):
            torque, speed, _ = leg["motors"][j]
            kp = torque / math.radians(3.0)  # full torque at 3 deg of error
            acts.append(f'<position joint="j{i}_{j}" kp="{kp}" kv="{torque / speed}" '
                        f'forcerange="{-torque} {torque}" forcelimited="true"/>')
    return f"""<mujoco>
  <option timestep="{MJ_STEP_S}" integrator="implicitfast" cone="elliptic" impratio="10"/>
  <worldbody>
    <geom type="plane" size="5 5 0.1" friction="{FOOT_FRICTION}"/>
    <body name="body" pos="0 0 {z0}">
      <freejoint/>
      <geom type="box" size="{bx / 2} {by / 2} {bz / 2}" mass="{spec['body_mass']}" friction="{BODY_FRICTION}"/>{''.join(legs_xml)}
    </body>
  </worldbody>
  <actuator>{''.join(acts)}</actuator>
</mujoco>"""


def replay_mujoco(spec):
    import mujoco

    model = mujoco.MjModel.from_xml_string(mjcf(spec))
    data = mujoco.MjData(model)
    rows = spec["rows"]
    n_legs = len(spec["legs"])
    r0 = rows[0]
    for i in range(n_legs):
        for j in range(2):
            data.joint(f"j{i}_{j}").qpos[0] = math.radians(float(r0[f"q_{i}_{j}"]))
    mujoco.mj_forward(model, data)
    ticks = int(round(0.02 / MJ_STEP_S))
    path = []
    for k, row in enumerate(rows):
        for i in range(n_legs):
            for j in range(2):
                data.ctrl[2 * i + j] = math.radians(float(row[f"target_{i}_{j}"]))
        x, y = data.qpos[0], data.qpos[1]
        w, qx, qy, qz = data.qpos[3:7]
        roll = math.atan2(2 * (w * qx + qy * qz), 1 - 2 * (qx * qx + qy * qy))
        pitch = math.asin(max(-1.0, min(1.0, 2 * (w * qy - qz * qx))))
        yaw = math.atan2(2 * (w * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))
        path.append((float(row["t"]), x * 1e3, y * 1e3, math.degrees(yaw), tilt_deg(roll, pitch)))
        if k + 1 < len(rows):
            mujoco.mj_step(model, data, nstep=ticks)
    return path


def unwrapped_yaw(path, i0):
    total = 0.0
    for a, b in zip(path[i0:], path[i0 + 1:]):
        d = b[3] - a[3]
        total += d - 360.0 * round(d / 360.0)
    return total


def compare(run_dir, rows, path):
    m = json.loads((run_dir / "metrics.json").read_text())
    t0 = m.get("ready_s", 0.0)
    i0 = next(k for k, r in enumerate(rows) if float(r["t"]) >= t0)
    s_dx = float(rows[-1]["x_mm"]) - float(rows[i0]["x_mm"])
    s_dy = float(rows[-1]["y_mm"]) - float(rows[i0]["y_mm"])
    p_dx, p_dy = path[-1][1] - path[i0][1], path[-1][2] - path[i0][2]
    dur = float(rows[-1]["t"]) - float(rows[i0]["t"])
    s_d, p_d = math.hypot(s_dx, s_dy), math.hypot(p_dx, p_dy)
    return {"run": run_dir.name, "robot": m.get("robot"), "from_s": round(float(rows[i0]["t"]), 3),
            "duration_s": round(dur, 3), "strider_sim_distance_mm": round(s_d, 1),
            "other_distance_mm": round(p_d, 1),
            "difference_pct": round(100.0 * (p_d - s_d) / s_d, 1) if s_d > 1e-6 else None,
            "strider_sim_heading_deg": round(float(rows[-1]["yaw_deg"]) - float(rows[i0]["yaw_deg"]), 1),
            "other_heading_deg": round(unwrapped_yaw(path, i0), 1),
            "strider_sim_max_tilt_deg": m.get("max_tilt_deg"),
            "other_max_tilt_deg": round(max(p[4] for p in path[i0:]), 2)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--run", required=True, help="strider-sim output folder")
    ap.add_argument("--cli", required=True, help="the strider CLI")
    ap.add_argument("--engine", choices=("pybullet", "mujoco"), default="pybullet")
    ap.add_argument("--json", help="write the comparison here")
    a = ap.parse_args()
    try:
        engine = __import__(a.engine)
    except ImportError:
        print(f"SKIP: {a.engine} is not installed")
        return 77
    run_dir = pathlib.Path(a.run)
    spec = robot_spec(run_dir, a.cli)
    path = replay_pybullet(spec) if a.engine == "pybullet" else replay_mujoco(spec)
    out = compare(run_dir, spec["rows"], path)
    out["engine"] = a.engine
    out["engine_version"] = str(getattr(engine, "__version__", None) or engine.getAPIVersion())
    print(json.dumps(out))
    if a.json:
        pathlib.Path(a.json).write_text(json.dumps(out) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
