"""The Routh-sphere field (mg-eq) for the peers of the work-precision benchmark.

The peers (heyoka, SciPy, Hairer's Fortran dop853) need the right-hand side in their own
language. It is written here once, generic over the arithmetic: `field(p, x)` uses only + - * /
so the same function runs on floats (SciPy), on heyoka expressions (heyoka compiles it), on
mpmath numbers and on SymPy symbols (from which the Fortran right-hand side is generated).
run.py's `check_fields` compares it with routh's own field at random points before any timing.

omega = I_Q^{-1} M with I_Q = I + m r^2 E - m r r^T (om-m) by Sherman-Morrison;
r = R gamma + a e3; U = m G (r, gamma); dgamma/dt = gamma x omega;
dM/dt = M x omega + m dr/dt x (omega x r) + gamma x dU/dgamma (mg-eq): `field_literal`.

`field` is the same function of x (on all of R^6, not only on |gamma| = 1) written shorter by
two exact identities, as routh's crates/routh-ball/src/field.rs writes it (a fair comparison needs the same
formula): a x (b x c) = b (a, c) - c (a, b) with (dgamma/dt, omega) = (dgamma/dt, gamma) = 0
gives m dr/dt x (omega x r) = -m R (dgamma/dt, com) omega = m R a (dgamma/dt)_3 omega
(com = -a e3); dU/dgamma = m G (2 R gamma + a e3) and gamma x gamma = 0 give
gamma x dU/dgamma = m G a (gamma_2, -gamma_1, 0). So

dM/dt = M x omega + m R a (dgamma/dt)_3 omega + m G a (gamma_2, -gamma_1, 0).

check_model.py shows that both forms agree with routh's field.
"""
import pathlib
import tomllib

ROOT = pathlib.Path(__file__).resolve().parents[2]
CASES = {
    "default": ROOT / "cases" / "default.toml",
    "nogravity": pathlib.Path(__file__).resolve().parent / "cases" / "nogravity.toml",
    "tilted": pathlib.Path(__file__).resolve().parent / "cases" / "tilted.toml",
}


def load(case):
    """Parameters (m, R, a, I1, I2, I3, G) and initial state (gamma, M) of a case file."""
    doc = tomllib.loads(CASES[case].read_text())
    b = doc["body"]
    p = dict(m=b["m"], R=b["R"], a=b["a"], I1=b["I1"], I2=b.get("I2", b["I1"]), I3=b["I3"], G=b["G"])
    g = doc["initial"]["gamma"]
    w = doc["initial"]["omega"]
    r = [p["R"] * g[0], p["R"] * g[1], p["R"] * g[2] + p["a"]]
    # M = I_Q omega = I omega + m r x (omega x r) = I omega + m (r^2 omega - (r, omega) r)
    rr = sum(c * c for c in r)
    rw = sum(r[i] * w[i] for i in range(3))
    inertia = [p["I1"], p["I2"], p["I3"]]
    m_vec = [inertia[i] * w[i] + p["m"] * (rr * w[i] - rw * r[i]) for i in range(3)]
    return p, list(g) + m_vec


def omega_of(p, x):
    g1, g2, g3, M1, M2, M3 = x
    m, R, a = p["m"], p["R"], p["a"]
    r1, r2, r3 = R * g1, R * g2, R * g3 + a
    mr2 = m * (r1 * r1 + r2 * r2 + r3 * r3)
    i1, i2, i3 = 1.0 / (p["I1"] + mr2), 1.0 / (p["I2"] + mr2), 1.0 / (p["I3"] + mr2)
    ar1, ar2, ar3 = r1 * i1, r2 * i2, r3 * i3
    am1, am2, am3 = M1 * i1, M2 * i2, M3 * i3
    c = m * (r1 * am1 + r2 * am2 + r3 * am3) / (1.0 - m * (r1 * ar1 + r2 * ar2 + r3 * ar3))
    return (am1 + ar1 * c, am2 + ar2 * c, am3 + ar3 * c), (r1, r2, r3)


def field(p, x):
    """(mg-eq) at x = (gamma, M), by the identities of the module's documentation."""
    g1, g2, g3, M1, M2, M3 = x
    (w1, w2, w3), _ = omega_of(p, x)
    gd1, gd2, gd3 = g2 * w3 - g3 * w2, g3 * w1 - g1 * w3, g1 * w2 - g2 * w1
    s = p["m"] * p["R"] * p["a"] * gd3
    ka = p["m"] * p["G"] * p["a"]
    return [
        gd1,
        gd2,
        gd3,
        M2 * w3 - M3 * w2 + s * w1 + ka * g2,
        M3 * w1 - M1 * w3 + s * w2 - ka * g1,
        M1 * w2 - M2 * w1 + s * w3,
    ]


def field_literal(p, x):
    """(mg-eq) at x = (gamma, M), term by term as the paper prints it."""
    g1, g2, g3, M1, M2, M3 = x
    m, R, a, G = p["m"], p["R"], p["a"], p["G"]
    (w1, w2, w3), (r1, r2, r3) = omega_of(p, x)
    gd1, gd2, gd3 = g2 * w3 - g3 * w2, g3 * w1 - g1 * w3, g1 * w2 - g2 * w1
    rd1, rd2, rd3 = R * gd1, R * gd2, R * gd3
    c1, c2, c3 = w2 * r3 - w3 * r2, w3 * r1 - w1 * r3, w1 * r2 - w2 * r1
    k = m * G
    u1, u2, u3 = 2 * R * k * g1, 2 * R * k * g2, 2 * R * k * g3 + a * k
    return [
        gd1,
        gd2,
        gd3,
        M2 * w3 - M3 * w2 + m * (rd2 * c3 - rd3 * c2) + g2 * u3 - g3 * u2,
        M3 * w1 - M1 * w3 + m * (rd3 * c1 - rd1 * c3) + g3 * u1 - g1 * u3,
        M1 * w2 - M2 * w1 + m * (rd1 * c2 - rd2 * c1) + g1 * u2 - g2 * u1,
    ]


def energy(p, x):
    """H1 = (M, omega) + 2U of (int-g)."""
    (w1, w2, w3), (r1, r2, r3) = omega_of(p, x)
    return x[3] * w1 + x[4] * w2 + x[5] * w3 + 2 * p["m"] * p["G"] * (r1 * x[0] + r2 * x[1] + r3 * x[2])
