# %% [markdown]
# # The Routh sphere from Python
#
# A Jupyter-style script (cells marked `# %%`; open it in Jupyter with jupytext or run it as a
# script). It simulates the default top-heavy Routh sphere, compares the simulation with the
# exact solution by quadrature, finds the turning points of the tilt with an event, and draws
# the tilt, the error against the quadrature and the path of the contact point on the plane.

# %%
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import routh

body, x0, _, _, _ = routh.default_case()
print(body)

# %% [markdown]
# Simulate to t = 10 with DOP853 at 1e-12, with the motion in space (`full=True`), dense
# output, and the maxima of the tilt theta as events (theta-dot crossing zero downwards).

# %%
t = np.linspace(0.0, 10.0, 2001)
result = routh.simulate(body, x0, 10.0, t_eval=t, full=True, dense_output=True,
                        events=routh.Event("theta_dot", direction=-1.0))
print(result.message, "steps:", result.steps, "nfev:", result.nfev)
theta = np.arccos(np.clip(result.y[2], -1.0, 1.0))

# %% [markdown]
# The exact solution by quadrature: turning points, period, precession.

# %%
exact = routh.ExactSolution(body, x0)
assert exact.period is not None and exact.precession_advance is not None  # a nutation
theta_min, theta_max = exact.theta_range
print(f"period T = {exact.period:.12f}, precession per period = {exact.precession_advance:.12f} rad")
print(f"maxima of theta found by the event: {result.t_events[0][:3]} ...")
print(f"their spacing - T: {np.max(np.abs(np.diff(result.t_events[0]) - exact.period)):.1e}")
error = np.max(np.abs(result.y[:6] - exact(t)), axis=0)
print(f"max |simulation - quadrature| = {error.max():.1e}")

# %% [markdown]
# The figure: theta(t) with the turning points, the difference from the quadrature, and the
# contact point's path on the plane.

# %%
fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
ax = axes[0]
ax.plot(t, np.degrees(theta), lw=1.0, label="simulate (DOP853)")
ax.axhline(np.degrees(theta_min), color="grey", ls="--", lw=0.8, label="turning points (quadrature)")
ax.axhline(np.degrees(theta_max), color="grey", ls="--", lw=0.8)
ax.plot(result.t_events[0], np.degrees(np.arccos(result.y_events[0][:, 2])), "v", ms=5,
        label="event theta_dot = 0")
ax.set_xlabel("t")
ax.set_ylabel("tilt theta (degrees)")
ax.set_title("Nutation of the tilt")
ax.set_ylim(np.degrees(theta_min) - 1.0, np.degrees(theta_max) + 5.0)
ax.legend(fontsize=7, loc="upper center", ncol=2)
ax = axes[1]
ax.semilogy(t[1:], error[1:], lw=0.8)
ax.set_xlabel("t")
ax.set_ylabel("max |x_simulate - x_exact|")
ax.set_title("Simulation against the quadrature")
ax = axes[2]
assert result.space is not None  # full=True
contact = result.space["contact"]
ax.plot(contact[0], contact[1], lw=0.8)
ax.plot(contact[0, 0], contact[1, 0], "o", ms=4, label="start")
ax.plot(contact[0, -1], contact[1, -1], "s", ms=4, label="t = 10")
ax.set_aspect("equal")
ax.set_xlabel("x")
ax.set_ylabel("y")
ax.set_title("Path of the contact point")
ax.legend(fontsize=7)
fig.tight_layout()
out = os.environ.get("ROUTH_EXAMPLE_FIGURE", "nutation.png")
fig.savefig(out, dpi=110)
print("wrote", out)
