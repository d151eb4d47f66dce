"""`routh.lyapunov`: the Lyapunov exponents of a ball on |gamma| = 1 against the command-line
tool's JSON and the integrable models' zero exponents, and bad arguments.

Each tolerance is stated with its reason; each check has a negative control.
"""

import json
import pathlib
import subprocess

import numpy as np
import pytest

import routh

ROOT = pathlib.Path(__file__).resolve().parents[2]
BINARY = ROOT / "target" / "release" / "routh"


def test_default_case_has_zero_exponents_and_the_divergence_check():
    # The default case over its t = 100 with the default schedule (transient 10): the five
    # exponents are below 0.05 (measured 0.026: they tend to 0 as ln T / T on the integrable
    # motion), and their sum equals the mean divergence to 1e-10 (Liouville's formula;
    # measured 5.2e-14). Negative control: over t = 5 the largest is 0.55.
    body, x0, t_end, rtol, atol = routh.default_case()
    r = routh.lyapunov(body, x0, t_end, rtol=rtol, atol=atol)
    assert len(r["exponents"]) == 5
    assert max(abs(l) for l in r["exponents"]) < 0.05
    assert abs(r["sum_of_exponents"] - r["divergence_mean"]) < 1e-10
    assert len(r["history"]["times"]) == 100
    assert "case" not in r
    short = routh.lyapunov(body, x0, 5.0)
    assert max(abs(l) for l in short["exponents"]) > 0.05


@pytest.mark.skipif(not BINARY.exists(), reason="the CLI is not built")
def test_same_numbers_as_the_command_line_tool():
    # The same library call behind both: the exponents agree to the last bit (JSON writes the
    # shortest decimal that reads back to the same double).
    cli = subprocess.run(
        [str(BINARY), "lyapunov", "--json", "--t-end", "20"],
        cwd=ROOT, check=True, capture_output=True, text=True,
    )
    expected = json.loads(cli.stdout)
    body, x0, *_ = routh.default_case()
    r = routh.lyapunov(body, x0, 20.0)
    assert r["exponents"] == expected["exponents"]
    assert r["divergence_mean"] == expected["divergence_mean"]


def test_chaplygin_ball_and_bad_arguments():
    # Chaplygin's ball (`cases/chaplygin.toml`) over t = 100: below 0.05 (measured 0.035).
    ball, x0, *_ = routh.load_case(ROOT / "cases" / "chaplygin.toml")
    r = routh.lyapunov(ball, x0, 100.0)
    assert max(abs(l) for l in r["exponents"]) < 0.05
    body, x0, *_ = routh.default_case()
    for kwargs, needle in [
        ({"interval": -1.0}, "interval"),
        ({"interval": float("nan")}, "interval"),
        ({"transient": 100.0}, "transient"),
        ({"method": "taylor"}, "method"),
        ({"rtol": 1.0}, "rtol"),
    ]:
        with pytest.raises(ValueError, match=needle):
            routh.lyapunov(body, x0, 100.0, **kwargs)
