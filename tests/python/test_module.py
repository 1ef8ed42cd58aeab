"""The Python module against the C++ API (tests/python/py_reference.cpp), the command line
(`swept bvh --json`, `swept plan --json`, their error messages) and closed-form distances."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import swept
from conftest import box, merge, sphere, write_problem, write_stl


def random_poses(rng, k, spread=3.0):
    """(k, 7): translations in a cube of side 2 * spread, random unnormalised quaternions."""
    t = rng.uniform(-spread, spread, size=(k, 3))
    q = rng.normal(size=(k, 4))
    q *= rng.uniform(0.5, 2.0, size=(k, 1))  # not normalised: the binding must normalise as the C++ API does
    return np.concatenate([t, q], axis=1)


def quat_to_matrix(p7):
    """(K, 7) -> (K, 4, 4) homogeneous matrices (NumPy only)."""
    x, y, z, w = (p7[:, 3:7] / np.linalg.norm(p7[:, 3:7], axis=1, keepdims=True)).T
    m = np.zeros((len(p7), 4, 4))
    m[:, 0, 0] = 1 - 2 * (y * y + z * z); m[:, 0, 1] = 2 * (x * y - z * w); m[:, 0, 2] = 2 * (x * z + y * w)
    m[:, 1, 0] = 2 * (x * y + z * w); m[:, 1, 1] = 1 - 2 * (x * x + z * z); m[:, 1, 2] = 2 * (y * z - x * w)
    m[:, 2, 0] = 2 * (x * z - y * w); m[:, 2, 1] = 2 * (y * z + x * w); m[:, 2, 2] = 1 - 2 * (x * x + y * y)
    m[:, :3, 3] = p7[:, :3]
    m[:, 3, 3] = 1
    return m


@pytest.fixture(scope="module")
def meshes(tmp_path_factory):
    """Two meshes written as STL: a sphere (960 triangles) and three boxes (36 triangles)."""
    d = tmp_path_factory.mktemp("meshes")
    sv, sf = sphere(1.5, 16, 32)
    bv, bf = merge(box((-1, -1, -1), (1, 0.5, 0.8)), box((1.2, -0.3, -0.2), (2.0, 0.3, 0.4)),
                   box((-2.5, 0.5, -0.5), (-1.5, 1.5, 0.5)))
    a, b = str(d / "sphere.stl"), str(d / "boxes.stl")
    write_stl(a, sv, sf, "sphere")
    write_stl(b, bv, bf, "boxes")
    return {"a": a, "b": b, "a_arrays": (sv, sf), "b_arrays": (bv, bf)}


# ---- arrays in and out ---------------------------------------------------------------------------
def test_mesh_from_arrays_keeps_the_arrays():
    v, f = box((0, 0, 0), (1, 2, 3))
    m = swept.Mesh(v, f, name="box")
    assert len(m) == 12 and m.name == "box" and m.unit == "mm" and m.file == ""
    assert m.vertices is v and m.faces is f  # float64 / int64 C-contiguous: no copy
    tri = m.triangles
    assert tri.shape == (12, 3, 3) and not tri.flags.writeable
    np.testing.assert_array_equal(tri, v[f])
    np.testing.assert_array_equal(m.bounds, [[0, 0, 0], [1, 2, 3]])
    # other dtypes are converted (int32 faces, float32 vertices) with the same triangles
    m32 = swept.Mesh(v.astype(np.float32), f.astype(np.int32))
    assert m32.vertices.dtype == np.float64 and m32.faces.dtype == np.int64
    np.testing.assert_array_equal(m32.triangles, tri)


def test_mesh_load_views_the_soup(meshes):
    m = swept.Mesh.load(meshes["a"])
    sv, sf = meshes["a_arrays"]
    assert len(m) == len(sf) and m.file == meshes["a"] and m.unit == "mm"
    assert m.vertices.shape == (3 * len(sf), 3) and not m.vertices.flags.writeable
    np.testing.assert_array_equal(m.faces, np.arange(3 * len(sf)).reshape(-1, 3))
    np.testing.assert_array_equal(m.triangles, sv[sf])  # exact: the STL holds every double's repr
    # the view keeps the soup alive after the Mesh is gone
    tri = m.triangles
    del m
    np.testing.assert_array_equal(tri, sv[sf])
    # units: the same file in metres
    m_m = swept.Mesh.load(meshes["a"], unit="m")
    np.testing.assert_allclose(m_m.triangles, sv[sf] / 1000, rtol=1e-15)


def test_bvh_stats_equal_the_command_line(meshes, swept_cli):
    m = swept.Mesh.load(meshes["a"])
    out = subprocess.run([swept_cli, "bvh", meshes["a"], "--fitter", "all", "--split", "all", "--json"],
                         check=True, capture_output=True, text=True).stdout
    rows = json.loads(out)["meshes"][0]["fitters"]
    assert len(rows) >= 6 and len(rows) % 3 == 0  # every fitter x every split rule
    for row in rows:
        st = swept.BVH(m, fitter=row["fitter"], split=row["split"]).stats()
        assert st["triangles"] == len(m)
        for k in ("fitter", "split", "nodes", "depth", "bytes"):
            assert st[k] == row[k], k
        for k in ("total_surface_area", "total_volume"):
            assert st[k] == pytest.approx(row[k], rel=1e-12), k  # the CLI prints 17 digits


# ---- agreement with the C++ API --------------------------------------------------------------------
@pytest.mark.parametrize("fitter", ["inertia", "pqp"])
def test_queries_agree_with_the_cpp_api(meshes, py_reference, tmp_path, fitter):
    rng = np.random.default_rng(20261124)
    k = 300
    pa, pb = random_poses(rng, k, 0.5), random_poses(rng, k, 3.0)
    poses_file = tmp_path / "poses.txt"
    with open(poses_file, "w") as f:
        for i in range(k):
            f.write(" ".join(repr(float(x)) for x in np.concatenate([pa[i], pb[i]])) + "\n")
    tol = 0.25
    out = subprocess.run([py_reference, meshes["a"], meshes["b"], fitter, repr(tol), str(poses_file)],
                         check=True, capture_output=True, text=True).stdout
    ref = np.array([[float(x) for x in line.split()] for line in out.splitlines()])
    assert ref.shape == (k, 11)

    a = swept.BVH(swept.Mesh.load(meshes["a"]), fitter=fitter)
    b = swept.BVH(swept.Mesh.load(meshes["b"]), fitter=fitter)
    d = swept.distance(a, b, pa, pb)
    assert d.distance.shape == (k,) and d.point_a.shape == (k, 3) and d.triangle_a.dtype == np.int64
    np.testing.assert_allclose(d.distance, ref[:, 0], rtol=0, atol=1e-12)
    np.testing.assert_allclose(d.point_a, ref[:, 1:4], rtol=0, atol=1e-12)
    np.testing.assert_allclose(d.point_b, ref[:, 4:7], rtol=0, atol=1e-12)
    np.testing.assert_array_equal(d.triangle_a, ref[:, 7].astype(np.int64))
    np.testing.assert_array_equal(d.triangle_b, ref[:, 8].astype(np.int64))
    assert d.exact.all()
    c = swept.collide(a, b, pa, pb)
    np.testing.assert_array_equal(c.colliding, ref[:, 9] == 1)
    assert 0 < c.colliding.sum() < k, "the seeded poses should give both outcomes"
    t = swept.tolerance(a, b, pa, pb, tol)
    np.testing.assert_array_equal(t.within, ref[:, 10] == 1)
    np.testing.assert_array_equal(t.within, d.distance < tol)

    # the same poses as 4x4 matrices, and serially: the same answers
    dm = swept.distance(a, b, quat_to_matrix(pa), quat_to_matrix(pb), threads=1)
    np.testing.assert_allclose(dm.distance, d.distance, rtol=0, atol=1e-12)
    d1 = swept.distance(a, b, pa, pb, threads=1)
    np.testing.assert_array_equal(d1.distance, d.distance)
    np.testing.assert_array_equal(d1.triangle_b, d.triangle_b)


def test_motion_clearance_agrees_with_the_cpp_api(meshes, py_reference, tmp_path):
    rng = np.random.default_rng(11)
    k = 60
    pa = random_poses(rng, k, 0.5)
    start, end = random_poses(rng, k, 4.0), random_poses(rng, k, 4.0)
    start[:, 0] += 3  # B starts beside A, and ends anywhere: some motions free, some not
    margin = 0.1
    f = tmp_path / "motions.txt"
    with open(f, "w") as out:
        for i in range(k):
            out.write(" ".join(repr(float(x)) for x in np.concatenate([pa[i], start[i], end[i]])) + "\n")
    text = subprocess.run([py_reference, "motion", meshes["a"], meshes["b"], "inertia", repr(margin), str(f)],
                          check=True, capture_output=True, text=True).stdout
    ref = np.array([[float(x) for x in line.split()] for line in text.splitlines()])
    assert ref.shape == (k, 5)
    a, b = swept.BVH(swept.Mesh.load(meshes["a"])), swept.BVH(swept.Mesh.load(meshes["b"]))
    m = swept.motion_clearance(a, b, pa, start, end, margin=margin)
    np.testing.assert_array_equal(m.free, ref[:, 0] == 1)
    assert 0 < m.free.sum() < k, "the seeded motions should give both outcomes"
    np.testing.assert_allclose(m.t_blocked, ref[:, 1], rtol=0, atol=1e-12)
    np.testing.assert_allclose(m.distance_at_block, ref[:, 2], rtol=0, atol=1e-12)
    np.testing.assert_allclose(m.min_distance, ref[:, 3], rtol=0, atol=1e-12)
    np.testing.assert_array_equal(m.distance_queries, ref[:, 4].astype(np.int64))


def test_distance_witnesses_checked_in_numpy(meshes):
    """Independent of the library: the closest points lie on the reported triangles (placed by the
    poses, in NumPy), are `distance` apart, and no vertex pair of the two meshes is closer."""
    rng = np.random.default_rng(5)
    k = 200
    pa, pb = random_poses(rng, k, 0.5), random_poses(rng, k, 4.0)
    (av, af), (bv, bf) = meshes["a_arrays"], meshes["b_arrays"]
    a, b = swept.BVH(swept.Mesh(av, af)), swept.BVH(swept.Mesh(bv, bf))
    d = swept.distance(a, b, pa, pb)
    ma, mb = quat_to_matrix(pa), quat_to_matrix(pb)
    np.testing.assert_allclose(np.linalg.norm(d.point_a - d.point_b, axis=1), d.distance, rtol=1e-12, atol=1e-12)
    for i in range(k):
        wa = av @ ma[i, :3, :3].T + ma[i, :3, 3]
        wb = bv @ mb[i, :3, :3].T + mb[i, :3, 3]
        for tri, point in ((wa[af[d.triangle_a[i]]], d.point_a[i]), (wb[bf[d.triangle_b[i]]], d.point_b[i])):
            # barycentric coordinates of the point in its triangle: inside, and on its plane
            e1, e2, r = tri[1] - tri[0], tri[2] - tri[0], point - tri[0]
            g = np.array([[e1 @ e1, e1 @ e2], [e1 @ e2, e2 @ e2]])
            u, v = np.linalg.solve(g, [r @ e1, r @ e2])
            assert u >= -1e-9 and v >= -1e-9 and u + v <= 1 + 1e-9, (i, u, v)
            assert np.linalg.norm(tri[0] + u * e1 + v * e2 - point) < 1e-9
        closest_vertices = np.sqrt(((wa[:, None, :] - wb[None, :, :]) ** 2).sum(-1)).min()
        assert d.distance[i] <= closest_vertices + 1e-12


def test_distance_closed_form_and_broadcasting():
    v, f = box((0, 0, 0), (1, 1, 1))
    a = swept.BVH(swept.Mesh(v, f))
    b = swept.BVH(swept.Mesh(v, f), fitter="rapid2")
    gaps = np.linspace(0.5, 5.0, 10)
    poses = np.zeros((10, 7))
    poses[:, 0] = 1 + gaps
    poses[:, 1] = 0.3
    poses[:, 6] = 1
    d = swept.distance(a, b, None, poses)
    np.testing.assert_allclose(d.distance, gaps, rtol=0, atol=1e-14)
    assert np.all(d.point_a[:, 0] == 1) and np.allclose(d.point_b[:, 0], 1 + gaps)
    # one pose for A (4x4), K for B; the distance along a diagonal translation
    shift = np.eye(4)
    shift[:3, 3] = [-2, 0, 0]
    d2 = swept.distance(a, b, shift, poses)
    np.testing.assert_allclose(d2.distance, gaps + 2, atol=1e-14)
    # a single pose each: K = 1
    d3 = swept.distance(a, b, None, [3, 0, 0, 0, 0, 0, 1])
    assert d3.distance.shape == (1,) and d3.distance[0] == pytest.approx(2.0, abs=1e-14)
    # overlapping boxes collide, with all contacts listed as sorted pairs
    c = swept.collide(a, b, None, [[0.5, 0.5, 0.5, 0, 0, 0, 1], [5, 0, 0, 0, 0, 0, 1]], all_contacts=True)
    assert c.colliding.tolist() == [True, False]
    assert c.contacts[0].shape[1] == 2 and len(c.contacts[0]) > 0 and len(c.contacts[1]) == 0
    assert c.triangle_a[1] == -1
    pairs = [tuple(p) for p in c.contacts[0]]
    assert pairs == sorted(set(pairs))
    # K = 0
    assert swept.distance(a, b, None, np.zeros((0, 7))).distance.shape == (0,)


def test_motion_clearance():
    v, f = box((0, 0, 0), (1, 1, 1))
    a = swept.BVH(swept.Mesh(v, f))
    b = swept.BVH(swept.Mesh(v * 0.5, f))
    start = np.array([[3, 0, 0, 0, 0, 0, 1], [3, 0, 0, 0, 0, 0, 1]], dtype=float)
    end = np.array([[3, 0, 5, 0, 0, 0, 1], [-3, 0, 0, 0, 0, 0, 1]], dtype=float)  # beside / through A
    m = swept.motion_clearance(a, b, None, start, end, margin=0.5)
    assert m.free.tolist() == [True, False]
    assert m.min_distance[0] >= 0.5 and 0 < m.t_blocked[1] < 1
    np.testing.assert_allclose(m.reference, [0.25, 0.25, 0.25])
    assert m.radius == pytest.approx(np.sqrt(3) * 0.25)
    with pytest.raises(swept.Error, match="smaller than the body's radius"):
        swept.motion_clearance(a, b, None, start, end, radius=0.1)
    # Sliding over A's top face 1e-12 above the margin (by construction: B's bottom at z = 1.5,
    # A's top at z = 1): a bisection needs pieces ~1e-12 long; the exact sweep decides it.
    graze_from = np.array([[-3, 0, 1.5, 0, 0, 0, 1]], dtype=float)
    graze_to = np.array([[3, 0, 1.5, 0, 0, 0, 1]], dtype=float)
    g = swept.motion_clearance(a, b, None, graze_from, graze_to, margin=0.5 - 1e-12)
    assert g.free.tolist() == [True] and g.sweeps.tolist() == [1] and g.distance_queries[0] <= 66
    assert m.sweeps.tolist() == [0, 0]


# ---- planning ----------------------------------------------------------------------------------------
def test_plan_equals_the_command_line(tmp_path, swept_cli):
    path = write_problem(str(tmp_path), clearance=0.5)
    problem = swept.Problem.load(path)
    assert problem.clearance == 0.5 and problem.fitter == "inertia" and problem.unit == "mm"
    np.testing.assert_array_equal(problem.start, [0, 0, 3, 0, 0, 0, 1])
    r = swept.plan(problem, time_limit=60, threads=1)
    assert r.solved and r.status == "solved" and r.path.shape == (r.waypoints, 7)
    np.testing.assert_allclose(r.path[0], problem.start, atol=1e-12)
    np.testing.assert_allclose(r.path[-1], problem.goal, atol=1e-12)
    assert r.min_clearance >= 0.5
    cli = json.loads(subprocess.run([swept_cli, "plan", path, "--json", "-q", "--threads", "1", "--time-limit", "60"],
                                    check=True, capture_output=True, text=True).stdout)
    assert r.path_hash == cli["path_hash"] and r.waypoints == cli["waypoints"] and r.message == cli["message"]
    assert r.path_length == cli["path_length"] and r.min_clearance == cli["min_clearance"]
    assert r.queries == cli["queries"] and r.nodes_checked == cli["nodes_checked"]
    # a scene reused, another clearance on a copy: the original problem is unchanged
    scene = swept.Scene(problem)
    p2 = problem.copy()
    p2.clearance = 0.25
    assert problem.clearance == 0.5
    r2 = swept.plan(p2, threads=2, scene=scene)
    assert r2.solved and r2.min_clearance >= 0.25
    r3 = swept.plan(problem, threads=2, scene=scene)
    assert r3.path_hash == r.path_hash  # the same path at any thread count, scene loaded or given
    assert scene.obstacle_tree.stats()["triangles"] == scene.obstacle_triangles == 108
    # a query budget: the same stop at any thread count, and as the command line says it
    stops = [swept.plan(problem, threads=t, scene=scene, max_queries=3) for t in (1, 2)]
    assert [s.status for s in stops] == ["no_path_budget"] * 2
    assert stops[0].queries == stops[1].queries and stops[0].queries["distance"] >= 3
    cli = json.loads(subprocess.run([swept_cli, "plan", path, "--json", "-q", "--max-queries", "3"],
                                    capture_output=True, text=True).stdout)
    assert not cli["solved"] and cli["message"] == stops[0].message and "budget of 3" in cli["message"]
    assert swept.plan(problem, scene=scene, max_queries=10**9).path_hash == r.path_hash
    with pytest.raises(swept.Error, match="max_queries must be a positive"):
        swept.plan(problem, scene=scene, max_queries=0)


def test_plan_seed_is_another_draw_of_the_trees(tmp_path, swept_cli):
    # The suite's house is solved by the trees, whose samples the seed shifts.
    subprocess.run([swept_cli, "scene", "house", "-o", str(tmp_path / "house")], check=True, capture_output=True)
    path = str(tmp_path / "house" / "problem.toml")
    problem = swept.Problem.load(path)
    assert problem.seed == 0
    scene = swept.Scene(problem)
    r0 = swept.plan(problem, scene=scene)
    r3 = swept.plan(problem, scene=scene, seed=3)
    assert r0.solved and r3.solved and r0.seed == 0 and r3.seed == 3 and r3.path_hash != r0.path_hash
    p3 = problem.copy()
    p3.seed = 3
    assert problem.seed == 0 and swept.plan(p3, threads=1, scene=scene).path_hash == r3.path_hash
    cli = json.loads(subprocess.run([swept_cli, "plan", path, "--json", "-q", "--seed", "3"],
                                    check=True, capture_output=True, text=True).stdout)
    assert cli["path_hash"] == r3.path_hash and cli["seed"] == 3
    with pytest.raises(swept.Error, match="seed must be >= 0, not -1"):
        p3.seed = -1
    with pytest.raises(swept.Error, match="seed must be >= 0, not -2"):
        swept.plan(problem, scene=scene, seed=-2)


def test_problem_notes_name_what_a_cfg_asks_of_ompl(tmp_path, swept_cli):
    # The suite's house writes an OMPL.app .cfg with [benchmark] and [planner] sections; an
    # `objective` line added to [problem] is a second note. The TOML has none. As `swept plan`.
    subprocess.run([swept_cli, "scene", "house", "-o", str(tmp_path / "house")], check=True, capture_output=True)
    assert swept.Problem.load(str(tmp_path / "house" / "problem.toml")).notes == []
    cfg = tmp_path / "house" / "house.cfg"
    text = cfg.read_text().replace("[problem]\n", "[problem]\nobjective = length\n", 1)
    cfg.write_text(text)
    notes = swept.Problem.load(str(cfg)).notes
    assert len(notes) == 2
    assert "objective = length: OMPL's optimization objective, not used" in notes[0]
    assert "[benchmark] and [planner]" in notes[1] and "house.cfg:" in notes[1]
    cli = json.loads(subprocess.run([swept_cli, "plan", str(cfg), "--json", "-q"],
                                    capture_output=True, text=True).stdout)
    assert cli["notes"] == notes


def test_scene_warnings_name_what_reading_left_out(tmp_path, swept_cli):
    # An OBJ obstacle whose first object holds a point and a line only: that part is left out of
    # the scene, and Scene.warnings says so, as `swept plan --json` lists it.
    (tmp_path / "obstacles.obj").write_text("o marks\nv 0 0 0\nv 1 0 0\np 1\nl 1 2\n"
                                            "o wall\nv 10 -50 -50\nv 10 50 -50\nv 10 50 50\nv 10 -50 50\nf 3 4 5 6\n")
    (tmp_path / "body.stl").write_text("solid b\nfacet normal 0 0 1\nouter loop\nvertex -1 -1 0\nvertex 1 -1 0\n"
                                       "vertex 0 1 0\nendloop\nendfacet\nendsolid b\n")
    problem_file = tmp_path / "problem.toml"
    problem_file.write_text('unit = "mm"\n[[obstacle]]\nfile = "obstacles.obj"\n[[body]]\nfile = "body.stl"\n'
                            "[start]\ntranslation = [0, 0, 0]\n[goal]\ntranslation = [-20, 0, 0]\n"
                            "[bounds]\nmin = [-50, -50, -50]\nmax = [50, 50, 50]\n")
    scene = swept.Scene(swept.Problem.load(str(problem_file)))
    assert len(scene.warnings) == 1
    assert scene.warnings[0].startswith(str(tmp_path / "obstacles.obj") + ": part 'marks' has no triangles")
    assert scene.obstacle_triangles == 2
    cli = json.loads(subprocess.run([swept_cli, "plan", str(problem_file), "--json", "-q"],
                                    check=True, capture_output=True, text=True).stdout)
    assert cli["warnings"] == scene.warnings


# ---- errors: swept.Error with the command line's message --------------------------------------------
def cli_error(cli, *args):
    p = subprocess.run([cli, *args], capture_output=True, text=True)
    assert p.returncode == 1, p.stderr
    line = p.stderr.strip().splitlines()[-1]
    assert line.startswith("swept: error: ")
    return line[len("swept: error: "):]


def test_errors_carry_the_command_line_messages(tmp_path, swept_cli):
    bad = tmp_path / "bad.stl"
    bad.write_text("solid x\nfacet normal 0 0 0\n outer loop\n  vertex 0 0 0\n  vertex 1 zero 0\n")
    with pytest.raises(swept.Error) as e:
        swept.Mesh.load(str(bad))
    assert str(e.value) == cli_error(swept_cli, "bvh", str(bad))
    assert "line 5" in str(e.value)
    assert isinstance(e.value, ValueError)

    nan = tmp_path / "nan.stl"
    v, f = box((0, 0, 0), (1, 1, 1))
    v[5, 1] = np.nan
    write_stl(str(nan), v, f)
    with pytest.raises(swept.Error) as e:
        swept.Mesh.load(str(nan))
    assert str(e.value) == cli_error(swept_cli, "bvh", str(nan))

    with pytest.raises(swept.Error, match="missing.stl"):
        swept.Mesh.load(str(tmp_path / "missing.stl"))

    good = write_problem(str(tmp_path), name="p")
    text = open(good).read()
    typo = tmp_path / "typo.toml"
    typo.write_text(text.replace("clearance =", "clearence ="))
    with pytest.raises(swept.Error) as e:
        swept.Problem.load(str(typo))
    assert str(e.value) == cli_error(swept_cli, "plan", str(typo))
    assert "clearence" in str(e.value)

    # start closer than the clearance: bad input for `swept plan` (exit 1), swept.Error here
    tight = tmp_path / "tight.toml"
    tight.write_text(text.replace("clearance = 0.5", "clearance = 2.5"))
    with pytest.raises(swept.Error) as e:
        swept.plan(swept.Problem.load(str(tight)))
    assert str(e.value) == cli_error(swept_cli, "plan", str(tight))

    with pytest.raises(swept.Error) as e:
        swept.Problem.load(str(good)).fitter = "bogus"
    assert str(e.value) == cli_error(swept_cli, "plan", str(good), "--fitter", "bogus")


def test_bad_arrays_raise():
    v, f = box((0, 0, 0), (1, 1, 1))
    with pytest.raises(swept.Error, match=r"faces\[3\] = \(.*\): vertex 8 is past the 8 vertices"):
        f2 = f.copy()
        f2[3, 1] = 8
        swept.Mesh(v, f2)
    with pytest.raises(swept.Error, match="vertex -1 is negative"):
        f2 = f.copy()
        f2[0, 0] = -1
        swept.Mesh(v, f2)
    with pytest.raises(swept.Error, match=r"vertices\[2\] has a non-finite coordinate"):
        v2 = v.copy()
        v2[2, 0] = np.inf
        swept.Mesh(v2, f)
    with pytest.raises(swept.Error, match="faces: an array of integers is needed, not float64"):
        swept.Mesh(v, f.astype(float))
    with pytest.raises(swept.Error, match=r"vertices: the shape must be \(N, 3\)"):
        swept.Mesh(v[:, :2], f)
    with pytest.raises(swept.Error, match="unknown unit 'furlong'"):
        swept.Mesh(v, f, unit="furlong")
    with pytest.raises(swept.Error, match="empty|no triangles"):
        swept.BVH(swept.Mesh(v, f[:0]))
    with pytest.raises(swept.Error, match="unknown split rule 'median'"):
        swept.BVH(swept.Mesh(v, f), split="median")

    t = swept.BVH(swept.Mesh(v, f))
    good = np.array([[2, 0, 0, 0, 0, 0, 1.0]] * 3)
    with pytest.raises(swept.Error, match=r"poses_b: poses must have shape \(7,\), \(4, 4\), \(K, 7\) or \(K, 4, 4\), not \(3, 6\)"):
        swept.distance(t, t, None, good[:, :6])
    bad = good.copy()
    bad[1, 2] = np.nan
    with pytest.raises(swept.Error, match=r"poses_b\[1\]: non-finite value"):
        swept.distance(t, t, None, bad)
    bad = good.copy()
    bad[2, 3:] = 0
    with pytest.raises(swept.Error, match=r"poses_b\[2\]: zero quaternion"):
        swept.collide(t, t, None, bad)
    m = np.eye(4)
    m[0, 1] = 0.5
    with pytest.raises(swept.Error, match="poses_a: the rotation is not orthonormal"):
        swept.tolerance(t, t, m, good, 0.1)
    with pytest.raises(swept.Error, match="poses_a has 2 poses, poses_b has 3"):
        swept.distance(t, t, good[:2], good)
    with pytest.raises(swept.Error, match="poses_b: not an array of numbers"):
        swept.distance(t, t, None, "up")
    with pytest.raises(swept.Error, match="threads must be >= 0"):
        swept.distance(t, t, None, good, threads=-1)
    with pytest.raises(TypeError):
        swept.distance(t, "tree", None, good)


# ---- the GIL -------------------------------------------------------------------------------------------
def test_the_gil_is_released_during_a_batch():
    """A batch in one thread while this thread keeps running Python: the longest pause this thread
    sees is a small part of the batch (with the GIL held it would be the whole batch)."""
    sv, sf = sphere(1.0, 24, 48)
    a = swept.BVH(swept.Mesh(sv, sf))
    rng = np.random.default_rng(7)
    poses = random_poses(rng, 20000, 3.0)
    swept.distance(a, a, None, poses[:100])  # warm up
    t0 = time.perf_counter()
    swept.distance(a, a, None, poses, threads=1)
    serial = time.perf_counter() - t0
    k = int(min(len(poses) * max(0.6 / max(serial, 1e-6), 1), 400000))  # a batch of about 0.6 s or more
    poses = random_poses(rng, k, 3.0)

    done = threading.Event()
    window = {}

    def batch():
        window["start"] = time.perf_counter()
        swept.distance(a, a, None, poses, threads=1)
        window["end"] = time.perf_counter()
        done.set()

    th = threading.Thread(target=batch)
    ticks = []
    th.start()
    while not done.is_set():
        ticks.append(time.perf_counter())
        sum(range(200))  # pure Python work: needs the GIL
    th.join()
    start, end = window["start"], window["end"]
    inside = [t for t in ticks if start <= t <= end]
    assert len(inside) > 10, "this thread did not run while the batch ran"
    times = [start] + inside + [end]
    longest = max(b - a for a, b in zip(times, times[1:]))
    assert longest < 0.5 * (end - start), (longest, end - start)


def test_the_stubs_name_what_the_module_has():
    """_swept.pyi lists every public name of the extension, with every method and property."""
    import ast
    stub = ast.parse(open(os.path.join(os.path.dirname(swept.__file__), "_swept.pyi")).read())
    names = {}
    for node in stub.body:
        if isinstance(node, ast.ClassDef):
            names[node.name] = {n.name if isinstance(n, ast.FunctionDef) else n.target.id
                                for n in node.body if isinstance(n, (ast.FunctionDef, ast.AnnAssign))}
        elif isinstance(node, ast.FunctionDef):
            names[node.name] = set()
    module = {n for n in dir(swept._swept) if not n.startswith("__")}
    assert set(names) | {"__version__"} >= module and set(names) <= module
    for cls in ("Mesh", "BVH", "Problem", "Scene", "Assembly"):
        members = {n for n in dir(getattr(swept, cls)) if not n.startswith("_") or n in ("__len__", "__init__")}
        assert members - {"__init__"} <= names[cls], (cls, members - names[cls])
        assert names[cls] - {"__init__", "__len__", "__copy__", "__deepcopy__"} <= members, cls
    for fn in ("distance", "collide", "tolerance", "motion_clearance", "plan", "disassemble"):
        assert getattr(swept, fn).__doc__


def test_ctrl_c_stops_a_long_batch():
    """SIGINT during a batch of minutes raises KeyboardInterrupt after the current chunk (in a child
    interpreter, so that a late signal cannot reach pytest)."""
    code = textwrap.dedent("""\
        import os, signal, sys, threading, time
        import numpy as np, swept
        from conftest import sphere
        v, f = sphere(1.0, 24, 48)
        a = swept.BVH(swept.Mesh(v, f))
        poses = np.zeros((2_000_000, 7)); poses[:, 6] = 1; poses[:, 0] = np.linspace(0.5, 5, len(poses))
        threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
        t0 = time.perf_counter()
        try:
            swept.distance(a, a, None, poses, threads=1)
            print("finished")
        except KeyboardInterrupt:
            print("interrupted")
        """)
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([os.path.dirname(__file__), os.environ.get("PYTHONPATH", "")]))
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=240, env=env)
    assert p.stdout.strip() == "interrupted", (p.stdout, p.stderr)


def test_pickle_round_trips(meshes, tmp_path):
    """Meshes and trees pickle (for Dask and multiprocessing): the triangles travel and the tree is
    rebuilt, node for node the same (equal stats, equal answers)."""
    import pickle
    m = swept.Mesh.load(meshes["b"])
    m2 = pickle.loads(pickle.dumps(m))
    np.testing.assert_array_equal(m2.triangles, m.triangles)
    assert (m2.file, m2.unit, m2.name) == (m.file, m.unit, m.name)
    a = swept.BVH(swept.Mesh(*meshes["a_arrays"]), fitter="pqp", split="largest", leaf_size=2)
    b = swept.BVH(m)
    a2, b2 = pickle.loads(pickle.dumps(a)), pickle.loads(pickle.dumps(b))
    for t, t2 in ((a, a2), (b, b2)):
        s, s2 = t.stats(), t2.stats()
        s.pop("build_ms"), s2.pop("build_ms")
        assert s == s2
    poses = random_poses(np.random.default_rng(3), 50, 3.0)
    d, d2 = swept.distance(a, b, None, poses), swept.distance(a2, b2, None, poses)
    np.testing.assert_array_equal(d.distance, d2.distance)
    np.testing.assert_array_equal(d.triangle_a, d2.triangle_a)
    np.testing.assert_array_equal(d.triangle_b, d2.triangle_b)
    # a scene's tree (no Mesh object behind it) too, with its input triangle ids
    scene = swept.Scene(swept.Problem.load(write_problem(str(tmp_path))))
    o = scene.obstacle_tree
    o2 = pickle.loads(pickle.dumps(o))
    c, c2 = swept.distance(o, o, None, poses), swept.distance(o2, o2, None, poses)
    np.testing.assert_array_equal(c.distance, c2.distance)
    np.testing.assert_array_equal(c.triangle_b, c2.triangle_b)
