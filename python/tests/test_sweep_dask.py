"""Sweeps from Python: `routh.sweep` returns a pyarrow table equal to the rows of the CLI;
the same sweep split into chunks on a Dask LocalCluster of 2 worker processes gives the same
table row for row; the Parquet file written by `routh sweep` reads back with pyarrow equal to
the JSON of the same sweep; `columns=` chooses the columns as `routh sweep --columns` does."""

import json
import math
import os
import pathlib
import subprocess

import pyarrow as pa
import pyarrow.parquet as pq
import pytest

import routh

ROOT = pathlib.Path(__file__).resolve().parents[2]
BINARY = ROOT / "target" / "release" / "routh"

CASE = """
[body]
m = 1.0
R = 1.0
a = 0.3
I1 = 0.4
I3 = 0.5
G = 9.81
[initial]
gamma = [0.29552020666133955, 0.0, 0.955336489125606]
omega = [0.5, 0.2, 8.0]
[integration]
t_end = 2.0
rtol = 1e-8
atol = 1e-8
[sweep]
tilt = { range = [0.3, 1.4], n = 50 }
spin = { range = [3.0, 7.0], n = 41 }
"""

CHUNK = 250


def same(a, b):
    """Equal values, NaN and null alike; doubles compared exactly."""
    if a is None or b is None:
        return a is None and b is None
    if isinstance(a, float) and math.isnan(a):
        return isinstance(b, float) and math.isnan(b)
    return a == b


def assert_tables_equal(left: pa.Table, right: pa.Table):
    assert left.schema.names == right.schema.names
    assert left.num_rows == right.num_rows
    for name in left.schema.names:
        a, b = left.column(name).to_pylist(), right.column(name).to_pylist()
        bad = [i for i, (x, y) in enumerate(zip(a, b)) if not same(x, y)]
        assert not bad, f"column {name} differs at rows {bad[:5]}"


def test_the_sweep_is_a_pyarrow_table_with_the_case_in_its_metadata():
    t = routh.sweep(text=CASE, stop=10)
    assert isinstance(t, pa.Table)
    assert t.num_rows == 10
    assert t.schema.field("run").type == pa.uint64()
    assert t.schema.field("tilt").type == pa.float64()
    assert t.schema.field("status").type == pa.string()
    assert t.schema.metadata[b"routh.case"].decode() == CASE
    assert t.column("run").to_pylist() == list(range(10))
    assert set(t.column("status").to_pylist()) == {"ok"}
    df = t.to_pandas()
    assert list(df.columns[:3]) == ["run", "spin", "tilt"]
    with pytest.raises(ValueError, match="tilt"):
        routh.sweep(text=CASE.replace("n = 50", "n = 0"))
    with pytest.raises(ValueError, match="start"):
        routh.sweep(text=CASE, start=5, stop=3)


def test_columns_are_chosen_as_on_the_command_line():
    default = routh.sweep(text=CASE, stop=4)
    assert "H1_drift" in default.schema.names and "final_M3" in default.schema.names
    assert "period_quadrature" not in default.schema.names
    every = routh.sweep(text=CASE, stop=4, columns=["all"])
    assert every.schema.names[-1] == "precession_difference"
    assert every.column("period_quadrature").null_count == 0
    # The columns of both tables have the same values: a column does not depend on the others
    # (but for rhs_evals: locating the turning points of `events` costs field evaluations).
    names = [n for n in default.schema.names if n != "rhs_evals"]
    assert_tables_equal(every.select(names), default.select(names))
    only = routh.sweep(text=CASE, stop=4, columns=["quadrature", "final_M3"])
    assert only.schema.names[-3:] == ["final_M3", "period_quadrature", "precession_quadrature"]
    with pytest.raises(ValueError, match="^columns: unknown column `bogus`.*nutation"):
        routh.sweep(text=CASE, columns=["final", "bogus"])


def test_user_events_are_the_command_line_s():
    # The keyword as `routh sweep --events`: the columns of each event, counts and first
    # times; a direction counts a part of `both`; a bad event is a ValueError naming it.
    both = routh.sweep(text=CASE, stop=4, events=["gamma1 = 0", "gamma1 = 0 up"])
    assert both.schema.names[-4:] == ["event0_count", "event0_first_t", "event1_count", "event1_first_t"]
    counts, ups = both.column("event0_count").to_pylist(), both.column("event1_count").to_pylist()
    assert all(0 <= u <= c for u, c in zip(ups, counts)), (counts, ups)
    firsts = both.column("event0_first_t").to_pylist()
    assert all((c == 0) == (f is None) for c, f in zip(counts, firsts))
    # Control: the default columns have no event columns.
    assert "event0_count" not in routh.sweep(text=CASE, stop=4).schema.names
    with pytest.raises(ValueError, match="events"):
        routh.sweep(text=CASE, stop=4, events=["gamma1 = inf"])


def test_a_dask_local_cluster_of_two_processes_gives_the_single_process_table():
    distributed = pytest.importorskip("distributed")
    whole = routh.sweep(text=CASE)
    runs = whole.num_rows
    assert runs == 2050
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        futures = [
            client.submit(
                routh.sweep, text=CASE, start=start, stop=min(start + CHUNK, runs), threads=1
            )
            for start in range(0, runs, CHUNK)
        ]
        parts = client.gather(futures)
        pids = client.run(os.getpid)
    assert len(set(pids.values())) == 2 and os.getpid() not in pids.values()
    assert_tables_equal(pa.concat_tables(parts), whole)
    # Negative control: a chunk shifted by one run is not equal.
    shifted = routh.sweep(text=CASE, start=1, stop=11)
    with pytest.raises(AssertionError):
        assert_tables_equal(shifted, whole.slice(0, 10))


@pytest.mark.skipif(not BINARY.exists(), reason="the CLI is not built")
def test_parquet_of_the_cli_reads_back_equal_to_its_json(tmp_path):
    case = tmp_path / "sweep.toml"
    case.write_text(CASE.replace("n = 41", "n = 3"))
    out = tmp_path / "sweep.parquet"
    proc = subprocess.run(
        [str(BINARY), "sweep", "--case", str(case), "--out", str(out), "--json"],
        capture_output=True,
        text=True,
    )
    if "no Parquet output" in proc.stderr:
        pytest.fail("the CLI was built without its default feature `parquet`: " + proc.stderr)
    assert proc.returncode == 0, proc.stderr
    rows = json.loads(proc.stdout)["rows"]
    table = pq.read_table(out)
    meta = pq.ParquetFile(out).metadata.metadata
    assert meta[b"routh.case"].decode() == case.read_text()
    assert meta[b"routh.version"].decode() == routh.__version__
    assert table.num_rows == len(rows) == 150
    for name in table.schema.names:
        column = table.column(name).to_pylist()
        for i, row in enumerate(rows):
            assert same(column[i], row[name]), (name, i, column[i], row[name])
    # The Python sweep gives the same rows as the CLI.
    assert_tables_equal(
        table.select(table.schema.names),
        routh.sweep(path=str(case)).select(table.schema.names),
    )


def test_a_sweep_of_the_sliding_top_from_python():
    """`routh.sweep` of the tippe top of cases/tippe_top.toml over `contact.mu` (issue 35): the
    table has the contact's columns, the spun top with friction turns over (its final tilt
    near pi) and the frictionless one does not; the rolling law's columns are refused."""
    text = (ROOT / "cases" / "tippe_top.toml").read_text() + (
        '\n[sweep]\n"contact.mu" = { values = [0.0, 0.3] }\n'
    )
    table = routh.sweep(text=text)
    names = table.schema.names
    for name in ("contact.mu", "transitions", "tilt_final", "jellett_drift", "final_gamma3"):
        assert name in names, names
    rows = table.to_pylist()
    assert [r["status"] for r in rows] == ["ok", "ok"]
    tilt = {r["contact.mu"]: r["tilt_final"] for r in rows}
    assert tilt[0.3] > 3.0 and tilt[0.0] < 0.3, tilt
    assert all(r["jellett_drift"] <= 1e-9 for r in rows)
    with pytest.raises(ValueError, match="law = \"sliding\""):
        routh.sweep(text=text, columns=["integrals"])
