"""swept.study on a real Dask scheduler with two worker processes on 127.0.0.1: the table equals a
serial run row for row (every column but the volatile ones), and each worker builds a problem's
trees once per fitter."""
from __future__ import annotations

import csv
import json
import os
import subprocess
import sys
import textwrap
import time

import pytest

import swept
from swept import study as st
from conftest import write_cup_assembly, write_problem


def write_study(folder):
    probs = os.path.join(folder, "problems")
    for i, hole_x in enumerate([6.0, -5.0, 4.0]):
        write_problem(probs, name=f"cup{i}", hole_x=hole_x, time_limit=60.0)
    path = os.path.join(folder, "study.toml")
    with open(path, "w") as f:
        f.write(textwrap.dedent("""\
            [study]
            name = "cups"
            threads = 1
            [[problem]]
            glob = "problems/cup*.toml"
            [variants]
            fitter = ["inertia", "pqp"]
            clearance = [0.25, 0.5, 2.5]   # 2.5: the start is too close (an error row)
            time_limit = 60.0
            """))
    return path


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def comparable(rows):
    return [{k: v for k, v in r.items() if k not in st.VOLATILE_COLUMNS} for r in rows]


def test_load_study_expands_the_jobs(tmp_path):
    s = st.load_study(write_study(str(tmp_path)))
    assert s.name == "cups" and len(s.jobs) == 18
    assert [j.id for j in s.jobs] == list(range(18))
    assert (s.jobs[0].problem, s.jobs[0].fitter, s.jobs[0].clearance) == ("problems/cup0", "inertia", 0.25)
    assert (s.jobs[5].problem, s.jobs[5].fitter, s.jobs[5].clearance) == ("problems/cup0", "pqp", 2.5)
    assert s.jobs[6].problem == "problems/cup1"
    bad = tmp_path / "bad.toml"
    bad.write_text('[[problem]]\nfile = "x.toml"\n[variants]\nclearence = [1]\n')
    with pytest.raises(swept.Error, match=r"bad.toml: unknown key 'variants.clearence'"):
        st.load_study(str(bad))


def spawn(args, log):
    return subprocess.Popen([sys.executable, *args], stdout=log, stderr=subprocess.STDOUT, start_new_session=True)


def stop(procs):
    for p in procs:
        if p.poll() is None:
            p.terminate()
    for p in procs:
        try:
            p.wait(timeout=15)
        except subprocess.TimeoutExpired:
            p.kill()
            p.wait()


def test_cluster_table_equals_the_serial_run(tmp_path):
    study_file = write_study(str(tmp_path))
    serial = st.run_study(st.load_study(study_file), serial=True, progress=False)
    assert [r["status"] for r in serial].count("error") == 6
    assert all(r["solved"] for r in serial if r["clearance"] != 2.5)
    assert all("closer than" in r["message"] or "clearance" in r["message"] for r in serial if r["status"] == "error")
    st.write_csv(serial, str(tmp_path / "serial.csv"))

    sched_file = str(tmp_path / "scheduler.json")
    log = open(tmp_path / "dask.log", "w")
    procs = []
    try:
        procs.append(spawn(["-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1", "--port", "0",
                            "--no-dashboard", "--scheduler-file", sched_file], log))
        deadline = time.monotonic() + 60
        while not os.path.exists(sched_file):
            assert time.monotonic() < deadline, "the scheduler did not start"
            assert procs[0].poll() is None, "the scheduler exited"
            time.sleep(0.1)
        time.sleep(0.2)  # the file is written whole by then
        address = json.load(open(sched_file))["address"]
        assert address.startswith("tcp://127.0.0.1:")
        for _ in range(2):
            procs.append(spawn(["-m", "distributed.cli.dask_worker", "--scheduler-file", sched_file, "--nworkers", "1",
                                "--nthreads", "1", "--host", "127.0.0.1", "--no-dashboard", "--no-nanny"], log))
        from distributed import Client
        with Client(address, timeout=60) as c:
            c.wait_for_workers(2, timeout=60)
        out = str(tmp_path / "cluster.csv")
        run = subprocess.run([sys.executable, "-m", "swept.study", study_file, "--scheduler", address, "-o", out],
                             capture_output=True, text=True, timeout=240)
        assert run.returncode == 0, run.stderr
        assert "18 jobs: 12 solved, 0 without a path, 6 errors" in run.stderr
    finally:
        stop(procs)
        log.close()

    cluster_rows = read_csv(out)
    serial_rows = read_csv(str(tmp_path / "serial.csv"))
    assert [r["job"] for r in cluster_rows] == [str(i) for i in range(18)]
    assert comparable(cluster_rows) == comparable(serial_rows)
    # the JSON beside the CSV holds the same rows
    doc = json.load(open(str(tmp_path / "cluster.json")))
    assert doc["columns"] == list(st.COLUMNS) and doc["volatile_columns"] == list(st.VOLATILE_COLUMNS)
    assert [r["path_hash"] for r in doc["rows"]] == [r["path_hash"] or None for r in serial_rows]
    assert [r["path_length"] for r in doc["rows"]] == [r["path_length"] for r in serial]
    # two worker processes; each built a (problem, fitter) scene at most once
    workers = {r["worker"] for r in cluster_rows}
    assert 1 <= len(workers) <= 2
    built = [(r["worker"], r["problem"], r["fitter"]) for r in cluster_rows
             if r["scene_cached"] == "false" and r["status"] != "error"]
    assert len(built) == len(set(built))
    assert sum(r["scene_cached"] == "true" for r in cluster_rows) >= 18 - 2 * 6


def test_local_cluster_run(tmp_path):
    """No --scheduler: a local cluster of two worker processes is started and stopped."""
    study_file = write_study(str(tmp_path))
    s = st.load_study(study_file)
    s.jobs = [j for j in s.jobs if j.problem == "problems/cup1"]
    serial = st.run_study(s, serial=True, progress=False)
    st.clear_cache()
    local = st.run_study(s, workers=2, progress=False)
    assert st.deterministic_rows(local) == st.deterministic_rows(serial)


def test_command_line_serial_and_bad_input(tmp_path):
    """`python3 -m swept.study --serial -o X.csv` writes X.csv and X.json; a bad study file is exit 1
    with one `swept: error:` line naming the file and the key."""
    study_file = write_study(str(tmp_path))
    s = st.load_study(study_file)
    out = str(tmp_path / "serial.csv")
    run = subprocess.run([sys.executable, "-m", "swept.study", study_file, "--serial", "-q", "-o", out],
                         capture_output=True, text=True, timeout=240)
    assert run.returncode == 0, run.stderr
    rows = read_csv(out)
    assert len(rows) == len(s.jobs) == 18
    doc = json.load(open(str(tmp_path / "serial.json")))
    assert [r["job"] for r in doc["rows"]] == list(range(18)) and doc["name"] == "cups"
    bad = tmp_path / "bad.toml"
    bad.write_text('[study]\nthreads = -1\n[[problem]]\nfile = "x.toml"\n')
    run = subprocess.run([sys.executable, "-m", "swept.study", str(bad), "--serial"], capture_output=True, text=True,
                         timeout=60)
    assert run.returncode == 1
    assert run.stderr.strip() == f"swept: error: {bad}: study.threads must be an integer >= 0 (0: all cores)"
    missing = tmp_path / "missing.toml"
    missing.write_text('[[problem]]\nfile = "nowhere.toml"\n')
    rows = st.run_study(st.load_study(str(missing)), serial=True, progress=False)
    assert rows[0]["status"] == "error" and "nowhere.toml" in rows[0]["message"]


def test_assemblies_in_a_study(tmp_path):
    """[[assembly]] entries: one disassembly per (clearance, time limit), not per fitter; the order
    is the one seen by hand (the lid before the peg); a local two-worker cluster gives the serial
    table; an assembly that does not load is an error row."""
    write_problem(str(tmp_path / "problems"), name="cup0", time_limit=60.0)
    write_cup_assembly(str(tmp_path / "assemblies"))
    path = tmp_path / "study.toml"
    path.write_text(textwrap.dedent("""\
        [[problem]]
        file = "problems/cup0.toml"
        [[assembly]]
        file = "assemblies/cupset.toml"
        name = "cupset"
        [[assembly]]
        file = "assemblies/nowhere.toml"
        [variants]
        fitter = ["inertia", "pqp"]
        clearance = [0.25, 9.0]        # 9: nothing keeps 9 mm from the cup's walls
        time_limit = 1.0
        """))
    s = st.load_study(str(path))
    assert [(j.kind, j.problem, j.fitter, j.clearance) for j in s.jobs] == [
        ("plan", "problems/cup0", "inertia", 0.25), ("plan", "problems/cup0", "inertia", 9.0),
        ("plan", "problems/cup0", "pqp", 0.25), ("plan", "problems/cup0", "pqp", 9.0),
        ("disassemble", "cupset", None, 0.25), ("disassemble", "cupset", None, 9.0),
        ("disassemble", "assemblies/nowhere", None, 0.25), ("disassemble", "assemblies/nowhere", None, 9.0)]
    s.jobs = [j for j in s.jobs if j.kind == "disassemble"]
    serial = st.run_study(s, serial=True, progress=False)
    ok, tight, missing, _ = serial
    assert (ok["kind"], ok["status"], ok["solved"], ok["order"], ok["parts"], ok["removed"]) == \
        ("disassemble", "complete", True, "lid > peg", 3, 2)
    assert ok["time_limit"] == 1.0 and ok["fitter"] is None and len(ok["path_hash"]) == 16
    assert tight["status"] == "incomplete" and not tight["solved"] and "stay" in tight["message"]
    assert missing["status"] == "error" and "nowhere.toml" in missing["message"]
    st.clear_cache()
    local = st.run_study(s, workers=2, progress=False)
    assert st.deterministic_rows(local) == st.deterministic_rows(serial)
