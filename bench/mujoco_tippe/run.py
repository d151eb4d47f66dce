"""The tippe top in MuJoCo against routh (issue 35: "the comparison with MuJoCo").

    python3 bench/mujoco_tippe/run.py [--json PATH] [--routh PATH] [--quick | --fine]

from the repository root (nice it on a shared machine). The first run makes a venv in
bench/mujoco_tippe/.venv with MuJoCo and NumPy from PyPI and re-runs itself there.

The top is the one of cases/tippe_top.toml: a sphere of m = R = 1, its centre of mass a = 0.3
below the geometric centre on the symmetry axis, I1 = I2 = 0.37, I3 = 0.4 about the centre of
mass, G = 9.81, tilted 0.1 rad from its low position, spun at omega3 = 20 about its symmetry
axis, the centre of mass at rest. It inverts (the height of the centre of mass goes from
R - a = 0.7 to R + a = 1.3) under a sliding friction; under Coulomb's friction the slip stops
within t < 1 and the rolling top, which keeps its energy, does not invert.

What is measured, to t = 20, for each run (one row of the table):
  * inverts / inversion time: the first upward crossing of height 1 = R by the centre of
    mass (linear interpolation between steps or samples), and the final height;
  * the drift of Jellett's integral lambda = (L, r) (L the angular momentum about the centre
    of mass, r from the centre of mass to the contact point, the geometric one, centre - R z),
    max |lambda(t) - lambda(0)| / |lambda(0)|: conserved for any force at the contact point
    of a sphere, so it measures how well the contact is modelled as a force at one point;
  * the final energy T + U (routh's H1 / 2) and, under Coulomb's friction, when the slip
    stops (routh: its `stick` event; MuJoCo, whose soft contact never stops it exactly: the
    first time |v_P| < 1e-3);
  * the penetration, -min over time of (sphere centre height - R) (MuJoCo's contact is soft;
    routh's sphere stays on the plane, 0);
  * the wall time of the integration (MuJoCo: the Python stepping loop, which for model (b)
    includes the friction law computed in Python each step; routh: the whole command, and
    its own elapsed_s).

MuJoCo's models (Euler, its default integrator, unless RK4 is named; MuJoCo's default
solref = (0.02, 1) and solimp unless a row names a stiffer solref = (0.002, 1), which separates
the soft contact's share of the difference from routh from the time step's):
  (a) "coulomb": MuJoCo's own frictional contact, condim 3, friction mu = 0.3, with elliptic
      and pyramidal cones (condim 6, with torsional/rolling friction, is left out: routh's
      models have none);
  (b) "viscous": the contact frictionless (condim 1) and the case's law F = -mu N v_P applied
      each step through xfrc_applied (force at the centre of mass, xipos, plus the torque of F
      at the contact point about it), N the contact's normal force of the previous step
      (mj_contactForce), v_P the tangential velocity of the material point at the geometric
      contact point, from the state at the start of the step (zero-order hold: also under RK4
      the force is constant over a step).
routh's runs: the viscous law at the case's rtol = atol = 1e-12 and at 1e-8 (DOP853), and
Coulomb's friction (the case copied to a temp file with friction = "coulomb"); the initial
height, energy and Jellett's integral of both programs are printed side by side first.
"""
import argparse
import csv
import json
import math
import os
import pathlib
import platform
import subprocess
import sys
import tempfile
import time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
VENV = HERE / ".venv"
CASE = ROOT / "cases" / "tippe_top.toml"

# The top (cases/tippe_top.toml).
M, RAD, A, I1, I3, G = 1.0, 1.0, 0.3, 0.37, 0.4, 9.81
TILT, SPIN, MU, T_END = 0.1, 20.0, 0.3, 20.0
STIFF = (0.002, 1.0)  # a stiffer solref (time constant, damping ratio) than MuJoCo's (0.02, 1)
SLIP_STOP = 1e-3   # MuJoCo's "slip stops" time: the first time |v_P| < SLIP_STOP


def ensure_venv():
    """Re-run this script with the venv's python, making the venv first if it is missing."""
    py = VENV / "bin" / "python"
    if pathlib.Path(sys.prefix).resolve() == VENV.resolve():
        return
    if not py.exists():
        subprocess.run([sys.executable, "-m", "venv", str(VENV)], check=True)
        subprocess.run([str(VENV / "bin" / "pip"), "install", "--quiet", "mujoco", "numpy"], check=True)
    os.execv(str(py), [str(py), __file__, *sys.argv[1:]])


def mjcf(dt, integrator, condim, cone, solref=None):
    """The top on a plane. Both geoms carry mu (MuJoCo combines the two geoms' friction by max);
    solref (time constant, damping ratio) of both geoms if given, else MuJoCo's default."""
    fr = f"{MU} 0.005 0.0001" if condim > 1 else "0 0 0"
    attrs = f'condim="{condim}" friction="{fr}"' + ("" if solref is None else f' solref="{solref[0]} {solref[1]}"')

    return f"""
<mujoco model="tippe_top">
  <option timestep="{dt}" gravity="0 0 -{G}" integrator="{integrator}" cone="{cone}"/>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 1" {attrs}/>
    <body name="top" pos="0 0 {RAD}">
      <freejoint/>
      <inertial pos="0 0 {-A}" mass="{M}" diaginertia="{I1} {I1} {I3}"/>
      <geom name="ball" type="sphere" size="{RAD}" {attrs}/>
    </body>
  </worldbody>
</mujoco>"""


def initial_state():
    """qpos, qvel of the free joint: the sphere touching the plane, body z (the symmetry axis,
    pointing from the centre of mass to the centre) tilted by TILT about y from the vertical, so
    that the downward vertical in the body frame is routh's gamma = (sin 0.1, 0, -cos 0.1);
    angular velocity SPIN about body z (MuJoCo's free joint takes it in the body frame); the
    linear part is the velocity of the body origin (the sphere's centre), chosen so that the
    centre of mass is at rest: v_o = -omega x (com - o) (zero here, since omega is along the
    axis through both, but written out)."""
    import numpy as np
    quat = np.array([math.cos(TILT / 2), 0.0, math.sin(TILT / 2), 0.0])
    rot = quat_to_mat(quat[None, :])[0]
    omega_w = rot @ np.array([0.0, 0.0, SPIN])
    v_o = -np.cross(omega_w, rot @ np.array([0.0, 0.0, -A]))
    return np.concatenate([[0.0, 0.0, RAD], quat]), np.concatenate([v_o, [0.0, 0.0, SPIN]])


def quat_to_mat(q):
    """Rotation matrices (body to world) of an (n, 4) array of unit quaternions (w, x, y, z)."""
    import numpy as np
    w, x, y, z = q.T
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
    ], -2)


def observables(qpos, qvel):
    """Height of the centre of mass, Jellett's integral, energy, sphere centre height - R,
    from (n, 7) qpos and (n, 6) qvel of the free joint."""
    import numpy as np
    rot = quat_to_mat(qpos[:, 3:7])
    com_b = np.array([0.0, 0.0, -A])
    inertia = np.array([I1, I1, I3])
    wb = qvel[:, 3:6]
    height = qpos[:, 2] + rot[:, 2, :] @ com_b
    # Jellett in the body frame: L = I omega, r = (contact - com) = R * down_b - com_b,
    # down_b = R^T (0, 0, -1) = -(third row of rot).
    r_b = -RAD * rot[:, 2, :] - com_b
    jellett = np.einsum("ij,ij->i", inertia * wb, r_b)
    v_com = qvel[:, 0:3] + np.cross(np.einsum("nij,nj->ni", rot, wb), rot @ com_b)
    energy = (0.5 * M * np.einsum("ij,ij->i", v_com, v_com) + 0.5 * np.einsum("ij,ij->i", inertia * wb, wb)
              + M * G * height)
    # Slip: the tangential velocity of the material point at P = o - R z, v_o + omega x (P - o).
    slip = qvel[:, 0:3] + np.cross(np.einsum("nij,nj->ni", rot, wb), [0.0, 0.0, -RAD])
    slip = np.hypot(slip[:, 0], slip[:, 1])
    return height, jellett, energy, qpos[:, 2] - RAD, slip


def first_crossing(t, h, level=1.0):
    """First time h crosses level upward, linear interpolation; None if never."""
    import numpy as np
    idx = np.nonzero((h[:-1] < level) & (h[1:] >= level))[0]
    if len(idx) == 0:
        return None
    i = idx[0]
    return float(t[i] + (level - h[i]) * (t[i + 1] - t[i]) / (h[i + 1] - h[i]))


def run_mujoco(friction, dt, integrator="Euler", cone="elliptic", solref=None):
    """Integrate one MuJoCo model to T_END; friction is "coulomb" (model a) or "viscous" (b)."""
    import mujoco
    import numpy as np
    condim = 3 if friction == "coulomb" else 1
    model = mujoco.MjModel.from_xml_string(mjcf(dt, integrator, condim, cone, solref))
    data = mujoco.MjData(model)
    data.qpos[:], data.qvel[:] = initial_state()
    mujoco.mj_forward(model, data)
    body = model.body("top").id
    n = int(round(T_END / dt))
    qpos = np.empty((n + 1, 7))
    qvel = np.empty((n + 1, 6))
    qpos[0], qvel[0] = data.qpos, data.qvel
    f6 = np.zeros(6)
    xfrc = data.xfrc_applied[body]   # a view: writing into it sets the applied force
    normal = 0.0                     # N of the previous step (none before the first)
    start = time.perf_counter()
    for k in range(1, n + 1):
        if friction == "viscous":
            # State at the start of the step, in plain floats (faster than small numpy arrays).
            w, x, y, z = data.qpos[3:7]
            wx, wy, wz = data.qvel[3:6]
            # omega in the world frame: rot @ omega_body.
            ox = (1 - 2 * (y * y + z * z)) * wx + 2 * (x * y - w * z) * wy + 2 * (x * z + w * y) * wz
            oy = 2 * (x * y + w * z) * wx + (1 - 2 * (x * x + z * z)) * wy + 2 * (y * z - w * x) * wz
            # v_P = v_o + omega x (P - o), P - o = (0, 0, -R); its tangential (x, y) part.
            vpx = data.qvel[0] - RAD * oy
            vpy = data.qvel[1] + RAD * ox
            fx, fy = -MU * normal * vpx, -MU * normal * vpy
            # Lever arm from the centre of mass (xipos = o + rot com_b) to P: (0,0,-R) - rot com_b.
            lx = A * 2 * (x * z + w * y)
            ly = A * 2 * (y * z - w * x)
            lz = -RAD + A * (1 - 2 * (x * x + y * y))
            # torque = lever x F, with F = (fx, fy, 0).
            xfrc[:] = (fx, fy, 0.0, -lz * fy, lz * fx, lx * fy - ly * fx)
        mujoco.mj_step(model, data)
        if friction == "viscous":
            normal = 0.0
            for i in range(data.ncon):
                mujoco.mj_contactForce(model, data, i, f6)
                normal += f6[0]
        qpos[k], qvel[k] = data.qpos, data.qvel
    wall = time.perf_counter() - start
    t = np.arange(n + 1) * dt
    height, jellett, energy, gap, slip = observables(qpos, qvel)
    t_inv = first_crossing(t, height)
    # The soft contact never stops the slip exactly: the first time it falls below SLIP_STOP.
    stopped = np.nonzero(slip < SLIP_STOP)[0]
    label = {"coulomb": f"MuJoCo Coulomb, condim 3, {cone}", "viscous": "MuJoCo viscous (xfrc_applied), condim 1"}
    label = label[friction] + ("" if integrator == "Euler" else f", {integrator}")
    label += "" if solref is None else f", solref {solref[0]:g} {solref[1]:g}"
    return {
        "model": label,
        "step": f"dt = {dt:g}",
        "inverts": t_inv is not None,
        "inversion_time": t_inv,
        "final_height": float(height[-1]),
        "jellett_drift": float(np.max(np.abs(jellett - jellett[0])) / abs(jellett[0])),
        "penetration": float(-gap.min()),
        "wall_s": wall,
        "initial": {"height": float(height[0]), "energy": float(energy[0]), "jellett": float(jellett[0])},
        "energy_final": float(energy[-1]),
        "slip_stop": float(t[stopped[0]]) if len(stopped) else None,
        "slip_final": float(slip[-1]),
        "solref": model.geom_solref[0].tolist(),
        "solimp": model.geom_solimp[0].tolist(),
    }


def run_routh(exe, friction, tol):
    """routh simulate on the case (a temp copy for Coulomb's friction): JSON and CSV runs."""
    with tempfile.TemporaryDirectory() as tmp:
        case = CASE
        if friction == "coulomb":
            case = pathlib.Path(tmp) / "tippe_top_coulomb.toml"
            text = CASE.read_text()
            assert 'friction = "viscous"' in text
            case.write_text(text.replace('friction = "viscous"', 'friction = "coulomb"'))
        cmd = [exe, "simulate", "--case", str(case), "--rtol", repr(tol), "--atol", repr(tol)]
        start = time.perf_counter()
        out = subprocess.run(cmd + ["--json"], check=True, text=True, capture_output=True).stdout
        wall = time.perf_counter() - start
        summary = json.loads(out)
        csv_path = pathlib.Path(tmp) / "samples.csv"
        subprocess.run(cmd + ["--samples", "20001", "--out", str(csv_path)], check=True, capture_output=True)
        with open(csv_path) as f:
            rows = list(csv.DictReader(f))
    import numpy as np
    t = np.array([float(r["t"]) for r in rows])
    h = np.array([float(r["height"]) for r in rows])
    t_inv = first_crossing(t, h)
    init = summary["initial_state"]
    sticks = [tr["t"] for tr in summary.get("transitions", []) if tr["kind"] == "stick"]
    return {
        "model": f"routh {friction} ({summary['method'].upper()})",
        "step": f"rtol = atol = {tol:g}",
        "inverts": t_inv is not None,
        "inversion_time": t_inv,
        "final_height": summary["final_state"]["height"],
        "jellett_drift": summary["balance"]["jellett"],
        "penetration": 0.0,
        "wall_s": wall,
        "elapsed_s": summary["elapsed_s"],
        "steps": summary["steps"],
        "transitions": summary.get("transitions", []),
        # routh's H1 is twice the energy (README: H1 = (M, omega) + 2U).
        "initial": {"height": init["height"], "energy": init["energy"] / 2, "jellett": init["jellett"]},
        "energy_final": summary["final_state"]["energy"] / 2,
        "slip_stop": sticks[0] if sticks else None,
        "slip_final": summary["final_state"]["slip_speed"],
    }


def fmt(v, spec):
    return "-" if v is None else format(v, spec)


def table(rows):
    lines = ["| model | dt / tolerance | inverts | inversion time | final height | Jellett drift | final energy | slip stops | penetration | wall time |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        wall = f"{r['wall_s']:.3g} s"
        if "elapsed_s" in r:
            wall += f" (elapsed_s {r['elapsed_s']:.2g})"
        lines.append(f"| {r['model']} | {r['step']} | {'yes' if r['inverts'] else 'no'} | {fmt(r['inversion_time'], '.4f')} "
                     f"| {r['final_height']:.4f} | {r['jellett_drift']:.2e} | {r['energy_final']:.3f} | {fmt(r['slip_stop'], '.4f')} "
                     f"| {r['penetration']:.2e} | {wall} |")
    return "\n".join(lines)


DEFAULT_ROUTH = "target/release/routh"


def main():
    ensure_venv()
    import mujoco
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--json", type=pathlib.Path, help="also write the results as JSON here")
    ap.add_argument("--routh", default=DEFAULT_ROUTH,
                    help=f"the routh CLI (default {DEFAULT_ROUTH}, built by cargo build --release if missing)")
    ap.add_argument("--quick", action="store_true", help="dt = 1e-3 only (a few seconds)")
    ap.add_argument("--fine", action="store_true", help="also model (b) at dt = 1e-5 (about 1 min a run)")
    args = ap.parse_args()
    if args.routh == DEFAULT_ROUTH and not pathlib.Path(DEFAULT_ROUTH).exists():
        subprocess.run(["cargo", "build", "--release", "-p", "routh-cli"], check=True)

    rows = []
    for tol in (1e-12, 1e-8):
        rows.append(run_routh(args.routh, "viscous", tol))
    rows.append(run_routh(args.routh, "coulomb", 1e-12))
    dts = (1e-3,) if args.quick else (1e-3, 1e-4)
    # (friction, dt, integrator, cone, solref); solref None: MuJoCo's default (0.02, 1).
    runs = [("viscous", dt, "Euler", "elliptic", None) for dt in dts]
    runs += [("viscous", 1e-3, "RK4", "elliptic", None)]
    if not args.quick:
        # A stiffer contact (time constant 20 dt) separates the soft contact's share of the
        # difference from routh from the time step's.
        runs += [("viscous", 1e-4, "Euler", "elliptic", STIFF)]
    if args.fine:
        runs += [("viscous", 1e-5, "Euler", "elliptic", None), ("viscous", 1e-5, "Euler", "elliptic", STIFF)]
    runs += [("coulomb", dt, "Euler", cone, None) for dt in dts for cone in ("elliptic", "pyramidal")]
    runs += [("coulomb", 1e-3, "RK4", "elliptic", None)]
    for spec in runs:
        rows.append(run_mujoco(*spec))
        print(f"done: {rows[-1]['model']}, {rows[-1]['step']} ({rows[-1]['wall_s']:.1f} s)", file=sys.stderr)

    ref = rows[0]["initial"]
    mj = next(r for r in rows if r["model"].startswith("MuJoCo"))["initial"]
    print("Initial values (energy E = T + U, routh's H1 / 2):")
    for key in ("height", "energy", "jellett"):
        print(f"  {key:8s} routh {ref[key]:.15g}   MuJoCo {mj[key]:.15g}   difference {mj[key] - ref[key]:.1e}")
    print()
    print(table(rows))
    print()
    sol = next(r for r in rows if "solref" in r and "solref" not in r["model"])
    versions = {"mujoco": mujoco.__version__, "python": platform.python_version(), "numpy": __import__("numpy").__version__,
                "routh": subprocess.run([args.routh, "--version"], text=True, capture_output=True).stdout.strip()}
    print("Versions: " + ", ".join(f"{k} {v}" for k, v in versions.items()))
    print(f"MuJoCo contact: solref {sol['solref']}, solimp {sol['solimp']} (defaults) unless a row names its solref; margin 0; "
          f"Euler is MuJoCo's default (semi-implicit) integrator.")
    command = "python3 bench/mujoco_tippe/run.py" + (" --quick" if args.quick else "") + (" --fine" if args.fine else "") + (
        f" --routh {args.routh}" if args.routh != DEFAULT_ROUTH else "")
    print(f"Reproduce: {command}")
    if args.json:
        args.json.write_text(json.dumps({"versions": versions, "command": command, "rows": rows}, indent=2) + "\n")


if __name__ == "__main__":
    main()
