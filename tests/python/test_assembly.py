"""swept.Assembly and swept.disassemble: a fixture whose only order can be seen by hand (the lid
before the peg, the peg straight up), the same result as `swept disassemble --json` and its
path files, any number of jobs, and the command line's errors."""
from __future__ import annotations

import json
import os
import subprocess

import numpy as np
import pytest

import swept
from conftest import box, write_cup_assembly, write_stl


def test_lid_before_peg_and_the_peg_straight_up(tmp_path):
    a = swept.Assembly.load(write_cup_assembly(str(tmp_path)))
    assert a.names == ["cup", "peg", "lid"] and a.fixed == ["cup"] and len(a) == 3
    assert a.triangles == 5 * 12 + 12 + 12
    # the lid's mesh is where its pose puts it
    np.testing.assert_array_equal(a.mesh("lid").bounds, [[-12, -12, 10], [12, 12, 12]])
    np.testing.assert_array_equal(a.mesh(1).bounds, [[-2, -2, 0], [2, 2, 6]])

    r = swept.disassemble(a, jobs=1)
    assert r.complete and r.fixed == ("cup",) and r.interferences == []
    assert r.order == ["lid", "peg"]
    lid, peg = r.sequence
    assert lid.removed and lid.method == "pull" and lid.round == 1
    # the peg touches the floor and is boxed in by the walls: up is its only way out
    assert peg.removed and peg.method == "pull" and peg.round == 2
    np.testing.assert_allclose(peg.direction, [0, 0, 1], atol=1e-12)
    # path: from the mounted pose (identity) straight up, far enough to clear the cup's box
    assert peg.path.shape[1] == 7 and peg.path.shape[0] >= 2
    np.testing.assert_array_equal(peg.path[0], [0, 0, 0, 0, 0, 0, 1])
    np.testing.assert_allclose(peg.path[-1][:2], [0, 0], atol=1e-12)
    np.testing.assert_allclose(peg.path[-1][3:], [0, 0, 0, 1], atol=1e-12)
    assert peg.path[-1][2] == pytest.approx(peg.distance) and peg.distance > 10


def test_a_part_that_cannot_leave_names_its_blockers(tmp_path):
    """Lid fixed too: the peg stays, blocked upwards by the lid and sideways by the cup."""
    a = swept.Assembly.load(write_cup_assembly(str(tmp_path)))
    r = swept.disassemble(a, fixed=["cup", "lid"], plan_time=0.2)
    assert not r.complete and r.order == [] and set(r.fixed) == {"cup", "lid"}
    (peg,) = r.sequence
    assert not peg.removed and peg.parts == ("peg",) and peg.method is None
    assert set(peg.blockers) == {"cup", "lid"}
    up = [b for d, b in peg.blocking if np.allclose(d, [0, 0, 1])]
    assert up == [("lid",)]
    assert peg.path.shape == (0, 7) or peg.path.shape[0] <= 1


def test_the_same_as_the_command_line(tmp_path, swept_cli):
    toml = write_cup_assembly(str(tmp_path), peg_bottom=-1.0)  # the peg sunk 1 mm into the floor
    out = tmp_path / "paths"
    run = subprocess.run([swept_cli, "disassemble", toml, "--json", "-o", str(out), "--plan-time", "0.2"],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode in (0, 2), run.stderr
    cli = json.loads(run.stdout)
    r = swept.disassemble(toml, plan_time=0.2)
    assert r.complete == cli["complete"] and (run.returncode == 0) == r.complete
    assert r.tolerance == cli["tolerance"] and r.clearance == cli["clearance"] and r.unit == cli["unit"]
    assert list(r.fixed) == [p["name"] for p in cli["parts"] if p["fixed"]]
    # the interference is reported first, by both
    assert [list(f.parts) for f in r.interferences] == [f["parts"] for f in cli["interferences"]] == [["cup", "peg"]]
    assert [f.depth for f in r.interferences] == [f["depth"] for f in cli["interferences"]]
    assert r.interferences[0].depth > r.tolerance
    assert len(r.sequence) == len(cli["sequence"])
    for s, c in zip(r.sequence, cli["sequence"]):
        assert list(s.parts) == ([c["part"]] if "part" in c else c["parts"])
        assert s.removed == (c["status"] == "removed") and s.round == c["round"]
        assert list(s.blockers) == c["blockers"]
        if s.removed:
            assert s.method == c["method"] and s.distance == c["distance"]
            if s.method == "pull":
                assert s.direction.tolist() == c["direction"]
            doc = json.load(open(out / c["path"]))
            poses = np.array([p["translation"] + p["quaternion"] for p in doc["poses"]])
            np.testing.assert_array_equal(s.path, poses)
            assert s.reference.tolist() == doc["reference_point"]
        else:
            assert [(d.tolist(), list(b)) for d, b in s.blocking] == \
                   [(b["direction"], b["blockers"]) for b in c["blocking"]]


def test_the_same_result_at_any_number_of_jobs(tmp_path):
    a = swept.Assembly.load(write_cup_assembly(str(tmp_path)))
    one, two = swept.disassemble(a, jobs=1), swept.disassemble(a, jobs=2)
    assert one.order == two.order
    for s, t in zip(one.sequence, two.sequence):
        np.testing.assert_array_equal(s.path, t.path)
        assert s.distance == t.distance and s.blockers == t.blockers


def test_errors_carry_the_command_line_messages(tmp_path, swept_cli):
    bad = tmp_path / "bad.toml"
    bad.write_text('[[part]]\nfile = "nowhere.stl"\nfixd = true\n')
    run = subprocess.run([swept_cli, "disassemble", str(bad)], capture_output=True, text=True, timeout=60)
    assert run.returncode == 1
    message = run.stderr.strip().splitlines()[-1].removeprefix("swept: error: ")
    with pytest.raises(swept.Error) as e:
        swept.Assembly.load(str(bad))
    assert str(e.value) == message and "bad.toml" in message
    with pytest.raises(swept.Error, match="no part is named 'nut'"):
        swept.disassemble(write_cup_assembly(str(tmp_path)), fixed="nut")
    with pytest.raises(swept.Error, match="clearance must be"):
        swept.disassemble(write_cup_assembly(str(tmp_path)), clearance=float("nan"))
    with pytest.raises(swept.Error, match="nothing.toml"):
        swept.disassemble(str(tmp_path / "nothing.toml"))
    with pytest.raises(TypeError):
        swept.disassemble(42)


def test_a_folder_of_placed_meshes(tmp_path):
    """Every file a part, named by its stem; the largest is the base when none is marked fixed."""
    folder = tmp_path / "parts"
    folder.mkdir()
    write_stl(str(folder / "base.stl"), *box((-10, -10, -2), (10, 10, 0)))
    write_stl(str(folder / "block.stl"), *box((-1, -1, 0), (1, 1, 2)))
    r = swept.disassemble(str(folder))
    assert r.parts == ("base", "block") and r.fixed == ("base",) and r.complete and r.order == ["block"]


def test_what_must_come_off_first(tmp_path):
    """target='peg': the lid must come off first (the peg's only way out is up, through it), then
    the peg; nothing else moves. The lid as target needs nothing off. The cup is fixed."""
    a = swept.Assembly.load(write_cup_assembly(str(tmp_path)))
    r = swept.disassemble(a, target="peg", jobs=1)
    assert r.complete and r.targets == ("peg",) and r.fewest and r.lower_bound == 2
    assert r.order == ["lid", "peg"]
    np.testing.assert_allclose(r.sequence[1].direction, [0, 0, 1], atol=1e-12)
    assert [w.parts for w in r.why] == [("peg",), ("lid",)]
    up = [b for d, b in r.why[0].blocking if np.allclose(d, [0, 0, 1])]
    assert up == [("lid",)]
    lid = swept.disassemble(a, target=["lid"])
    assert lid.order == ["lid"] and lid.fewest
    with pytest.raises(swept.Error, match="fixed"):
        swept.disassemble(a, target="cup")
    with pytest.raises(swept.Error):
        swept.disassemble(a, target="nosuch")
