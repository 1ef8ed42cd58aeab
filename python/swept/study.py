"""Many independent planning and disassembly jobs over a Dask cluster, or serially: ``python3 -m swept.study``.

    python3 -m swept.study STUDY.toml [--scheduler tcp://HOST:8786 | --workers N | --serial]
                                      [-o results.csv] [--quiet]

A study file names problems and the variants to sweep; every combination is one job::

    [study]
    name = "boxes"              # optional
    threads = 1                 # planner threads per job (default 1: the cluster runs jobs side by side)
    time_limit = 60.0           # default time limit (seconds) when `variants.time_limit` is absent

    [[problem]]
    file = "problems/a.toml"    # relative to the study file; or `glob = "problems/*.toml"`
    name = "a"                  # optional, default: the path relative to the study file, no extension

    [[assembly]]                # optional: whole assemblies taken apart (swept.disassemble)
    file = "gearbox/assembly.toml"   # a TOML assembly file, a folder or a STEP file; or `glob`
    name = "gearbox"            # optional, as for problems

    [variants]                  # each optional; a list of values, or one value
    fitter = ["inertia", "pqp"]
    clearance = [0.5, 1.0]      # overrides the problem's [planner] clearance
    time_limit = [30.0]

A study needs at least one [[problem]] or [[assembly]]. For an assembly, `clearance` is the
clearance of swept.disassemble (default 0.01) and `time_limit` its seconds per planner attempt
(plan_time, default 60, a safety net behind the default budget of 20,000 distance queries per
attempt, which ends attempts the same way on every machine); `fitter` does not apply (its trees are always built with the default
fitter), so an assembly is not repeated per fitter. Its row's `status` is `complete` or
`incomplete`, `solved` whether every movable part came out, `order` the parts' removal order,
`path_hash` a hash of the order and every removal path, `waypoints` the poses of all paths.

Jobs are numbered problem by problem, then fitter, clearance, time limit (the order above), then
the assemblies by clearance and time limit. The
result table has one row per job, sorted by job id: the job's settings, the planner's outcome
and figures, and -- in the columns listed in VOLATILE_COLUMNS -- timings, the worker and whether
the worker's cached scene was reused. Every other column is identical, row for row, between a
cluster run and a serial run, as long as no job reaches its time limit (the planner is
deterministic until then). Workers load the meshes from the paths in the problem files (give
them a shared file system with the same absolute paths), and keep each problem's scene (meshes
and RSS trees) per fitter, so a tree is built once per worker, not once per job.
"""
from __future__ import annotations

import argparse
import csv
import glob as globmod
import hashlib
import io
import itertools
import json
import math
import os
import socket
import sys
import threading
import time
import tomllib
from dataclasses import dataclass, field
from typing import Any, Callable, Iterable, Optional, Sequence

import numpy as np

import swept

__all__ = ["Study", "Job", "COLUMNS", "VOLATILE_COLUMNS", "load_study", "run_study", "run_job",
           "write_csv", "write_json", "deterministic_rows", "main"]

#: Every column of the result table, in order.
COLUMNS: tuple[str, ...] = (
    "job", "kind", "problem", "file", "fitter", "clearance", "time_limit", "threads",
    "status", "solved", "message", "waypoints", "path_length", "translation_length",
    "rotation_length_rad", "min_clearance", "path_hash", "distance_queries", "nodes_checked",
    "edges_checked", "level", "parts", "removed", "order",
    "load_ms", "build_ms", "search_ms", "plan_ms", "wall_ms", "cpu_ms", "worker", "scene_cached",
)
#: Columns that differ between runs (timings, placement); left out of the equality of tables.
VOLATILE_COLUMNS: tuple[str, ...] = ("load_ms", "build_ms", "search_ms", "plan_ms", "wall_ms", "cpu_ms", "worker",
                                     "scene_cached")

_VARIANT_KEYS = ("fitter", "clearance", "time_limit")


@dataclass(frozen=True)
class Job:
    """One plan (a problem file) or one disassembly (an assembly) with the settings of one variant."""
    id: int
    problem: str          #: the problem's (or assembly's) name in the study
    file: str             #: absolute path of the problem file, assembly file or folder
    fitter: Optional[str]  #: None: the problem's own (always None for assemblies)
    clearance: Optional[float]
    time_limit: float     #: nan: the problem's own (assemblies: the default plan_time)
    threads: int
    kind: str = "plan"    #: "plan" | "disassemble"


@dataclass
class Study:
    path: str
    name: str
    jobs: list[Job] = field(default_factory=list)


class StudyError(swept.Error):
    """A malformed study file (the message names the file and the key)."""


def _as_list(value: Any) -> list:
    return list(value) if isinstance(value, (list, tuple)) else [value]


def _default_name(base: str, file: str) -> str:
    """A problem's default name: its path relative to the study file, without the extension."""
    rel = os.path.relpath(os.path.normpath(file), base)
    return os.path.splitext(rel)[0].replace(os.sep, "/")


def load_study(path: str | os.PathLike) -> Study:
    """Reads a study file and expands it into its jobs (see the module's documentation)."""
    path = os.fspath(path)
    try:
        with open(path, "rb") as f:
            doc = tomllib.load(f)
    except OSError as e:
        raise StudyError(f"{path}: cannot read the study file: {e.strerror or e}") from None
    except tomllib.TOMLDecodeError as e:
        raise StudyError(f"{path}: {e}") from None
    base = os.path.dirname(os.path.abspath(path))
    known = {"study", "problem", "assembly", "variants"}
    for key in doc:
        if key not in known:
            raise StudyError(f"{path}: unknown key '{key}' (study, problem, assembly, variants)")
    head = doc.get("study", {})
    if not isinstance(head, dict):
        raise StudyError(f"{path}: 'study' must be a table")
    for key in head:
        if key not in ("name", "threads", "time_limit"):
            raise StudyError(f"{path}: unknown key 'study.{key}' (name, threads, time_limit)")
    name = str(head.get("name", os.path.splitext(os.path.basename(path))[0]))
    threads = head.get("threads", 1)
    if not isinstance(threads, int) or isinstance(threads, bool) or threads < 0:
        raise StudyError(f"{path}: study.threads must be an integer >= 0 (0: all cores)")
    default_limit = head.get("time_limit")

    def entries_of(table: str) -> list[tuple[str, str]]:
        out: list[tuple[str, str]] = []
        entries = doc.get(table, [])
        if not isinstance(entries, list):
            raise StudyError(f"{path}: '{table}' must be an array of tables ([[{table}]])")
        for i, entry in enumerate(entries):
            where = f"{table}[{i}]"
            if not isinstance(entry, dict):
                raise StudyError(f"{path}: {where} must be a table")
            for key in entry:
                if key not in ("file", "glob", "name"):
                    raise StudyError(f"{path}: unknown key '{where}.{key}' (file, glob, name)")
            if ("file" in entry) == ("glob" in entry):
                raise StudyError(f"{path}: {where} needs one of 'file' or 'glob'")
            if "file" in entry:
                f = os.path.normpath(os.path.join(base, str(entry["file"])))
                out.append((str(entry["name"]) if "name" in entry else _default_name(base, f), f))
            else:
                matches = sorted(globmod.glob(os.path.join(base, str(entry["glob"]))))
                if not matches:
                    raise StudyError(f"{path}: {where}.glob '{entry['glob']}' matches no file")
                if "name" in entry:
                    raise StudyError(f"{path}: {where}: 'name' goes with 'file', not 'glob'")
                for f in matches:
                    out.append((_default_name(base, f), os.path.normpath(f)))
        return out

    problems = entries_of("problem")
    assemblies = entries_of("assembly")
    if not problems and not assemblies:
        raise StudyError(f"{path}: no [[problem]] or [[assembly]] entries")

    variants = doc.get("variants", {})
    if not isinstance(variants, dict):
        raise StudyError(f"{path}: 'variants' must be a table")
    for key in variants:
        if key not in _VARIANT_KEYS:
            raise StudyError(f"{path}: unknown key 'variants.{key}' ({', '.join(_VARIANT_KEYS)})")
    fitters = _as_list(variants.get("fitter", [None]))
    for fv in fitters:
        if fv is not None and fv not in ("pqp", "rapid2", "inertia"):
            raise StudyError(f"{path}: variants.fitter: unknown fitter '{fv}' (pqp, rapid2, inertia)")
    clearances = _as_list(variants.get("clearance", [None]))
    for c in clearances:
        if c is not None and (isinstance(c, bool) or not isinstance(c, (int, float)) or not c >= 0
                              or not math.isfinite(c)):
            raise StudyError(f"{path}: variants.clearance: {c!r} is not a number >= 0")
    limits = _as_list(variants.get("time_limit", [default_limit]))
    for t in limits:
        if t is not None and (isinstance(t, bool) or not isinstance(t, (int, float)) or not t > 0
                              or not math.isfinite(t)):
            raise StudyError(f"{path}: time_limit: {t!r} is not a positive number of seconds")

    study = Study(path=os.path.abspath(path), name=name)
    for (pname, pfile), fitter, clearance, limit in itertools.product(problems, fitters, clearances, limits):
        study.jobs.append(Job(id=len(study.jobs), problem=pname, file=pfile, fitter=fitter,
                              clearance=None if clearance is None else float(clearance),
                              time_limit=float(limit) if limit is not None else math.nan, threads=threads))
    for (aname, afile), clearance, limit in itertools.product(assemblies, clearances, limits):
        study.jobs.append(Job(id=len(study.jobs), problem=aname, file=afile, fitter=None,
                              clearance=None if clearance is None else float(clearance),
                              time_limit=float(limit) if limit is not None else math.nan, threads=threads,
                              kind="disassemble"))
    return study


# ---- what a worker runs ---------------------------------------------------------------------------
# Per process: problems by file, scenes (meshes + trees) by (file, fitter). A worker builds each
# tree once and keeps it for every later job of that problem and fitter; past SCENE_CACHE_SIZE
# scenes (environment SWEPT_STUDY_SCENES, default 32) the least recently used one is dropped.
SCENE_CACHE_SIZE = int(os.environ.get("SWEPT_STUDY_SCENES", "32"))
_cache_lock = threading.Lock()
_problems: dict[tuple, swept.Problem] = {}
_scenes: dict[tuple, swept.Scene] = {}  # in order of last use
_scene_locks: dict[tuple, threading.Lock] = {}
_assemblies: dict[tuple, swept.Assembly] = {}


def _file_key(file: str) -> tuple:
    st = os.stat(file)
    return (file, st.st_mtime_ns, st.st_size)


def _cached_scene(problem: swept.Problem, key: tuple, fitter: str) -> tuple[swept.Scene, bool]:
    skey = key + (fitter,)
    with _cache_lock:
        scene = _scenes.pop(skey, None)
        if scene is not None:
            _scenes[skey] = scene  # most recently used last
            return scene, True
        lock = _scene_locks.setdefault(skey, threading.Lock())
    with lock:  # one build per key even with several threads per worker
        with _cache_lock:
            scene = _scenes.get(skey)
        if scene is not None:
            return scene, True
        scene = swept.Scene(problem, fitter=fitter)
        with _cache_lock:
            _scenes[skey] = scene
            while len(_scenes) > max(SCENE_CACHE_SIZE, 1):
                del _scenes[next(iter(_scenes))]
        return scene, False


def clear_cache() -> None:
    """Forgets the problems and scenes this process keeps."""
    with _cache_lock:
        _problems.clear()
        _scenes.clear()
        _assemblies.clear()
        _scene_locks.clear()


def _fmt_float(x: Optional[float]) -> Optional[float]:
    return None if x is None else float(x)


def _sequence_hash(result: swept.DisassemblyResult) -> str:
    """16 hex digits over the removal order and every removal path's poses (exact doubles)."""
    h = hashlib.sha256()
    for step in result.sequence:
        h.update(("+".join(step.parts) + ("|removed" if step.removed else "|blocked") + "\n").encode())
        h.update(np.ascontiguousarray(step.path, dtype="<f8").tobytes())
    return h.hexdigest()[:16]


def _cached_load(cache: dict, file: str, what: str, load: Callable[[str], Any]) -> tuple[tuple, Any, bool]:
    """The file's object from this process's cache, or loaded and kept: (key, object, cached)."""
    try:
        key = _file_key(file)
    except OSError as e:
        raise swept.Error(f"{file}: cannot open the {what} ({e.strerror})") from None
    with _cache_lock:
        obj = cache.get(key)
    if obj is not None:
        return key, obj, True
    obj = load(file)
    with _cache_lock:
        cache[key] = obj
    return key, obj, False


def _run_disassembly(job: Job, row: dict) -> None:
    _, assembly, cached = _cached_load(_assemblies, job.file, "assembly", swept.Assembly.load)
    clearance = 0.01 if job.clearance is None else job.clearance
    plan_time = 60.0 if math.isnan(job.time_limit) else job.time_limit
    row.update(clearance=clearance, time_limit=plan_time, scene_cached=cached)
    r = swept.disassemble(assembly, clearance=clearance, plan_time=plan_time, jobs=job.threads)
    removed = [s for s in r.sequence if s.removed]
    stay = [n for s in r.sequence if not s.removed for n in s.parts]
    message = (f"{len(r.order)} of {len(r.parts) - len(r.fixed)} movable parts come out" +
               (f"; {', '.join(stay)} stay" if stay else "") +
               (f"; {len(r.interferences)} interferences" if r.interferences else ""))
    row.update(status="complete" if r.complete else "incomplete", solved=r.complete, message=message,
               waypoints=int(sum(s.path.shape[0] for s in removed)), path_hash=_sequence_hash(r),
               distance_queries=r.distance_queries, parts=len(r.parts), removed=len(r.order),
               order=" > ".join("+".join(s.parts) for s in removed), build_ms=r.time_ms["build"],
               search_ms=r.time_ms["sequence"], plan_ms=sum(r.time_ms.values()))


def run_job(job: Job) -> dict:
    """Runs one job in this process (a Dask worker, or the serial loop) and returns its row.
    Bad input (a problem file that does not load, a start in collision) is a row with status
    'error' and the message, not an exception."""
    t0, c0 = time.perf_counter(), time.process_time()
    row: dict[str, Any] = {c: None for c in COLUMNS}
    row.update(job=job.id, kind=job.kind, problem=job.problem, file=job.file, fitter=job.fitter,
               clearance=job.clearance, time_limit=None if math.isnan(job.time_limit) else job.time_limit,
               threads=job.threads, worker=f"{socket.gethostname()}:{os.getpid()}")
    if job.kind == "disassemble":
        try:
            _run_disassembly(job, row)
        except swept.Error as e:
            row.update(status="error", solved=False, message=str(e))
        row["wall_ms"] = (time.perf_counter() - t0) * 1e3
        row["cpu_ms"] = (time.process_time() - c0) * 1e3
        return row
    try:
        key, base, _ = _cached_load(_problems, job.file, "problem file", swept.Problem.load)
        problem = base.copy()
        if job.fitter is not None:
            problem.fitter = job.fitter
        if job.clearance is not None:
            problem.clearance = job.clearance
        if not math.isnan(job.time_limit):
            problem.time_limit = job.time_limit
        problem.threads = job.threads
        row.update(fitter=problem.fitter, clearance=problem.clearance, time_limit=problem.time_limit)
        scene, cached = _cached_scene(problem, key, problem.fitter)
        row.update(scene_cached=cached, load_ms=0.0 if cached else scene.load_ms,
                   build_ms=0.0 if cached else scene.build_ms)
        r = swept.plan(problem, scene=scene)
        row.update(status=r.status, solved=r.solved, message=r.message, waypoints=r.waypoints,
                   path_length=r.path_length, translation_length=r.translation_length,
                   rotation_length_rad=r.rotation_length_rad, min_clearance=_fmt_float(r.min_clearance),
                   path_hash=r.path_hash if r.solved else None, distance_queries=r.queries["distance"],
                   nodes_checked=r.nodes_checked, edges_checked=r.edges_checked, level=r.level,
                   search_ms=r.time_ms["search"], plan_ms=r.time_ms["total"])
    except swept.Error as e:
        row.update(status="error", solved=False, message=str(e))
    row["wall_ms"] = (time.perf_counter() - t0) * 1e3
    row["cpu_ms"] = (time.process_time() - c0) * 1e3  # this process's CPU time (all its threads)
    return row


# ---- running a study --------------------------------------------------------------------------------
class _Progress:
    """A progress bar on stderr: tqdm when installed, else one line redrawn. Only on a terminal,
    as the CLI's progress lines: a redirected stderr or a log never holds it."""

    def __init__(self, total: int, enabled: bool, label: str):
        enabled = enabled and sys.stderr.isatty()
        self.total, self.done, self.enabled, self.label = total, 0, enabled, label
        self.bar = None
        self.t0 = time.monotonic()
        if enabled:
            try:
                from tqdm import tqdm
                self.bar = tqdm(total=total, desc=label, unit="job", file=sys.stderr)
            except ImportError:
                self._draw()

    def _draw(self) -> None:
        width = 30
        filled = int(width * self.done / max(self.total, 1))
        sys.stderr.write(f"\r{self.label} [{'#' * filled}{'.' * (width - filled)}] {self.done}/{self.total} "
                         f"{time.monotonic() - self.t0:.1f} s")
        sys.stderr.flush()

    def update(self) -> None:
        self.done += 1
        if not self.enabled:
            return
        if self.bar is not None:
            self.bar.update(1)
        else:
            self._draw()

    def close(self) -> None:
        if not self.enabled:
            return
        if self.bar is not None:
            self.bar.close()
        else:
            sys.stderr.write("\n")


def _run_serial(jobs: Sequence[Job], progress: _Progress) -> list[dict]:
    rows = []
    for job in jobs:
        rows.append(run_job(job))
        progress.update()
    return rows


def _home_workers(jobs: Sequence[Job], workers: Sequence[str]) -> dict[int, str]:
    """A preferred worker per job, so that the jobs of one (problem, fitter) scene go to the same
    worker and the scene is loaded and its trees built on fewer workers: the scenes, largest job
    count first, each to the worker with the fewest jobs so far. Only a preference (Dask may run a
    job elsewhere, and steals work for idle workers); none when there are fewer scenes than
    workers."""
    groups: dict[tuple, list[int]] = {}
    for j in jobs:
        groups.setdefault((j.file, j.fitter), []).append(j.id)
    if len(workers) < 2 or len(groups) < len(workers):
        return {}
    load = {w: 0 for w in workers}
    home: dict[int, str] = {}
    for ids in sorted(groups.values(), key=lambda ids: (-len(ids), ids[0])):
        w = min(workers, key=lambda w: (load[w], w))
        load[w] += len(ids)
        for i in ids:
            home[i] = w
    return home


def _run_dask(jobs: Sequence[Job], client: Any, progress: _Progress) -> list[dict]:
    from distributed import as_completed
    # By reference to the importable module (under `python3 -m swept.study` this file runs as
    # __main__, whose functions cloudpickle would copy by value, with their module's locks).
    import swept.study
    home = _home_workers(jobs, sorted(client.scheduler_info().get("workers", {})))
    futures = [client.submit(swept.study.run_job, j, pure=False, key=f"swept-study-job-{j.id}",
                             workers=[home[j.id]] if j.id in home else None, allow_other_workers=True)
               for j in jobs]
    rows = []
    try:
        for fut in as_completed(futures):
            rows.append(fut.result())
            progress.update()
    finally:
        for fut in futures:
            fut.release()
    return rows


def run_study(study: Study, *, scheduler: Optional[str] = None, client: Any = None, workers: Optional[int] = None,
              serial: bool = False, progress: bool = True) -> list[dict]:
    """Runs every job of the study and returns the rows sorted by job id.

    serial: in this process, one job after the other. client: a distributed.Client to use.
    scheduler: the address of a running Dask scheduler (tcp://HOST:8786). Otherwise a local
    cluster of `workers` processes (default: the number of cores), one thread each, on 127.0.0.1,
    is started and stopped here."""
    bar = _Progress(len(study.jobs), progress, study.name)
    try:
        if serial:
            rows = _run_serial(study.jobs, bar)
        elif client is not None:
            rows = _run_dask(study.jobs, client, bar)
        else:
            from distributed import Client, LocalCluster
            if scheduler:
                with Client(scheduler) as c:
                    rows = _run_dask(study.jobs, c, bar)
            else:
                n = workers or os.cpu_count() or 1
                with LocalCluster(n_workers=n, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster, Client(cluster) as c:
                    rows = _run_dask(study.jobs, c, bar)
    finally:
        bar.close()
    rows.sort(key=lambda r: r["job"])
    return rows


def deterministic_rows(rows: Iterable[dict]) -> list[dict]:
    """The rows without the volatile columns: equal between any two runs of a study whose jobs
    finish within their time limits."""
    return [{k: v for k, v in r.items() if k not in VOLATILE_COLUMNS} for r in rows]


def _cell(v: Any) -> str:
    if v is None:
        return ""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return repr(v)  # shortest text that reads back to the same double
    return str(v)


def csv_text(rows: Sequence[dict]) -> str:
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(COLUMNS)
    for r in rows:
        w.writerow([_cell(r.get(c)) for c in COLUMNS])
    return out.getvalue()


def write_csv(rows: Sequence[dict], path: str) -> None:
    _write_atomically(path, csv_text(rows))


def _json_value(v: Any) -> Any:
    if isinstance(v, float) and not math.isfinite(v):
        return None if math.isnan(v) else ("inf" if v > 0 else "-inf")
    return v


def write_json(rows: Sequence[dict], path: str, study: Optional[Study] = None) -> None:
    doc = {
        "study": study.path if study else None,
        "name": study.name if study else None,
        "columns": list(COLUMNS),
        "volatile_columns": list(VOLATILE_COLUMNS),
        "rows": [{c: _json_value(r.get(c)) for c in COLUMNS} for r in rows],
    }
    _write_atomically(path, json.dumps(doc, indent=1) + "\n")


def _write_atomically(path: str, text: str) -> None:
    tmp = f"{path}.tmp{os.getpid()}"
    try:
        with open(tmp, "w", encoding="utf-8", newline="") as f:
            f.write(text)
        os.replace(tmp, path)
    except OSError as e:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise swept.Error(f"{path}: cannot write ({e.strerror or e})") from None


def _summary(rows: Sequence[dict], wall: float) -> str:
    solved = sum(1 for r in rows if r["solved"])
    errors = sum(1 for r in rows if r["status"] == "error")
    # An assembly counts as solved when it came apart completely.
    return f"{len(rows)} jobs: {solved} solved, {len(rows) - solved - errors} without a path, {errors} errors, {wall:.2f} s"


def main(argv: Optional[Sequence[str]] = None) -> int:
    ap = argparse.ArgumentParser(
        prog="python3 -m swept.study",
        description="Run a study (problems and assemblies x variants, one plan or disassembly per job) on a "
                    "Dask cluster or serially; "
                    "write the result table as CSV and JSON.")
    ap.add_argument("study", help="the study file (TOML)")
    where = ap.add_mutually_exclusive_group()
    where.add_argument("--scheduler", help="address of a running Dask scheduler, e.g. tcp://HOST:8786")
    where.add_argument("--serial", action="store_true", help="run the jobs in this process, one after the other")
    ap.add_argument("--workers", type=int, default=None,
                    help="worker processes of the local cluster (default: the number of cores)")
    ap.add_argument("-o", "--output", help="write the table to this CSV file and, beside it, the same rows as "
                                           "JSON (the name with .json); default: CSV on stdout")
    ap.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    args = ap.parse_args(argv)
    if args.workers is not None and args.workers < 1:
        ap.error("--workers must be >= 1")
    try:
        study = load_study(args.study)
        t0 = time.perf_counter()
        rows = run_study(study, scheduler=args.scheduler, workers=args.workers, serial=args.serial,
                         progress=not args.quiet)
        wall = time.perf_counter() - t0
        if args.output:
            stem, ext = os.path.splitext(args.output)
            csv_path = args.output if ext.lower() != ".json" else stem + ".csv"
            write_csv(rows, csv_path)
            write_json(rows, stem + ".json", study)
        else:
            sys.stdout.write(csv_text(rows))
        print(f"swept.study: {_summary(rows, wall)}", file=sys.stderr)
    except swept.Error as e:
        print(f"swept: error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
