"""The energy-momentum diagram from Python, against the command-line tool's JSON and against
independent facts: the focus-focus sleeping top lies below Routh's threshold, and the
monodromy around it is the one of a focus-focus point with one pinch."""

import json
import pathlib
import subprocess
import tempfile

import pytest

import routh

ROOT = pathlib.Path(__file__).resolve().parents[2]
# A coarse resolution keeps the test fast; the command is run with the same one.
COARSE = dict(tilts=60, grid=20, loop_points=32)


@pytest.fixture(scope="module")
def body():
    return routh.default_case()[0]


@pytest.fixture(scope="module")
def plane(body):
    return routh.diagram(body, 1.0, **COARSE)


def test_diagram_matches_the_command_line_tool(plane):
    binary = ROOT / "target" / "release" / "routh"
    with tempfile.TemporaryDirectory() as out:
        text = subprocess.run(
            [str(binary), "diagram", "--h3", "1", "--tilts", "60", "--grid", "20",
             "--loop-points", "32", "--out", out, "--json"],
            check=True, capture_output=True, text=True).stdout
    cli = json.loads(text)
    for key in ("H3", "window", "vertical_spins", "critical_curves", "focus_focus", "monodromy",
                "tori"):
        # The same computation of the same library, through serde_json both ways: equal.
        assert plane[key] == cli[key], key


def test_focus_focus_point_and_its_monodromy(body, plane):
    # At H3 = 1 the upper sleeping top spins below Routh's threshold (|H3| = 1.79 there):
    # one focus-focus point, and once around it the rotation number drops by exactly 1.
    assert len(plane["focus_focus"]) == 1
    ff = plane["focus_focus"][0]
    assert ff["H3"] == pytest.approx(1.0, abs=1e-12)
    upper = next(line for line in routh.sleeping_tops(body, 4.0) if line["pole"] == 1.0)
    assert ff["state"]["gamma"] == [0.0, 0.0, 1.0] and ff["stability"] == "focus-focus"
    assert abs(ff["H3"]) < upper["threshold_h3"]
    assert plane["monodromy"]["matrix"] == [[1, -1], [0, 1]]


def test_no_focus_focus_above_the_threshold(body):
    # The default case's own H3 (5.08) is above the threshold: both sleeping tops are stable.
    plane = routh.diagram(body, 5.0804, **COARSE)
    assert plane["focus_focus"] == [] and plane["monodromy"] is None


def test_sleeping_tops_change_type_at_routh_threshold(body):
    lines = routh.sleeping_tops(body, 4.0, samples=81)
    upper = next(line for line in lines if line["pole"] == 1.0)
    assert upper["threshold_h3"] == pytest.approx(1.7912, abs=1e-4)
    # Above the threshold elliptic; below it focus-focus, except at zero spin (H3 = 0), where
    # the complex quadruplet degenerates into two real pairs: hyperbolic.
    for spin in upper["spins"]:
        if spin["H3"] == 0.0:
            expected = "hyperbolic"
        elif abs(spin["H3"]) < upper["threshold_h3"]:
            expected = "focus-focus"
        else:
            expected = "elliptic"
        assert spin["stability"] == expected, spin["H3"]


@pytest.mark.parametrize("kwargs, name", [
    (dict(h3=float("nan")), "h3"),
    (dict(h3=1.0, tilts=1), "tilts"),
    (dict(h3=1.0, grid=10**9), "grid"),
])
def test_bad_arguments_raise_value_error(body, kwargs, name):
    with pytest.raises(ValueError, match=name):
        routh.diagram(body, **kwargs)


def test_sleeping_tops_refuse_bad_arguments(body):
    with pytest.raises(ValueError, match="samples"):
        routh.sleeping_tops(body, 1.0, samples=1)
    with pytest.raises(ValueError, match="h3_max"):
        routh.sleeping_tops(body, float("inf"))
