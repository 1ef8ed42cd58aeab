"""Shared helpers of the Python tests: box meshes, STL files and small planning problems, all
generated here (nothing downloaded)."""
from __future__ import annotations

import os
import textwrap

import numpy as np
import pytest

BOX_FACES = np.array([
    [0, 2, 1], [0, 3, 2],  # z = min
    [4, 5, 6], [4, 6, 7],  # z = max
    [0, 1, 5], [0, 5, 4],  # y = min
    [2, 3, 7], [2, 7, 6],  # y = max
    [1, 2, 6], [1, 6, 5],  # x = max
    [0, 4, 7], [0, 7, 3],  # x = min
], dtype=np.int64)


def box(lo, hi):
    """Vertices (8, 3) and faces (12, 3) of an axis-aligned box, outward normals."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    v = np.array([[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0],
                  [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]], dtype=np.float64)
    return v, BOX_FACES.copy()


def merge(*meshes):
    vs, fs, n = [], [], 0
    for v, f in meshes:
        vs.append(v)
        fs.append(f + n)
        n += len(v)
    return np.concatenate(vs), np.concatenate(fs)


def sphere(radius=1.0, n_lat=16, n_lon=32, centre=(0.0, 0.0, 0.0)):
    """A UV sphere: (n_lat - 1) * n_lon + 2 vertices, 2 * n_lon * (n_lat - 1) triangles."""
    verts = [[0, 0, radius]]
    for i in range(1, n_lat):
        th = np.pi * i / n_lat
        for j in range(n_lon):
            ph = 2 * np.pi * j / n_lon
            verts.append([radius * np.sin(th) * np.cos(ph), radius * np.sin(th) * np.sin(ph), radius * np.cos(th)])
    verts.append([0, 0, -radius])
    v = np.array(verts, dtype=np.float64) + np.asarray(centre, dtype=np.float64)
    faces = []
    for j in range(n_lon):
        faces.append([0, 1 + j, 1 + (j + 1) % n_lon])
    for i in range(n_lat - 2):
        for j in range(n_lon):
            a = 1 + i * n_lon + j
            b = 1 + i * n_lon + (j + 1) % n_lon
            faces.append([a, a + n_lon, b])
            faces.append([b, a + n_lon, b + n_lon])
    last = len(verts) - 1
    base = 1 + (n_lat - 2) * n_lon
    for j in range(n_lon):
        faces.append([base + j, last, base + (j + 1) % n_lon])
    return v, np.array(faces, dtype=np.int64)


def write_stl(path, vertices, faces, name="part"):
    """ASCII STL with every coordinate written exactly (repr of the double)."""
    with open(path, "w") as f:
        f.write(f"solid {name}\n")
        for tri in faces:
            f.write("facet normal 0 0 0\n outer loop\n")
            for k in tri:
                x, y, z = vertices[k]
                f.write(f"  vertex {x!r} {y!r} {z!r}\n")
            f.write(" endloop\nendfacet\n")
        f.write(f"endsolid {name}\n")


def write_problem(folder, name="problem", clearance=0.5, time_limit=30.0, hole_x=6.0):
    """A box cup (floor and four walls, 20 x 20 x 10 inside) with a lid whose square hole (6 x 6) is
    centred at x = hole_x, and a 4 x 4 x 4 body on the floor at the centre: the body must slide
    under the hole, then rise out. Writes <name>.toml and its meshes; returns the problem's path."""
    os.makedirs(folder, exist_ok=True)
    h = 3.0
    parts = [box((-12, -12, -2), (12, 12, 0)),          # floor
             box((-12, -12, 0), (-10, 12, 10)), box((10, -12, 0), (12, 12, 10)),
             box((-10, -12, 0), (10, -10, 10)), box((-10, 10, 0), (10, 12, 10)),
             # lid at z in [10, 12] with a hole [hole_x - h, hole_x + h] x [-h, h]
             box((-12, -12, 10), (hole_x - h, 12, 12)), box((hole_x + h, -12, 10), (12, 12, 12)),
             box((hole_x - h, -12, 10), (hole_x + h, -h, 12)), box((hole_x - h, h, 10), (hole_x + h, 12, 12))]
    ov, of = merge(*parts)
    bv, bf = box((-2, -2, -2), (2, 2, 2))
    write_stl(os.path.join(folder, f"{name}_cup.stl"), ov, of, "cup")
    write_stl(os.path.join(folder, f"{name}_body.stl"), bv, bf, "body")
    path = os.path.join(folder, f"{name}.toml")
    with open(path, "w") as f:
        f.write(textwrap.dedent(f"""\
            unit = "mm"
            [[obstacle]]
            file = "{name}_cup.stl"
            [[body]]
            file = "{name}_body.stl"
            [start]
            translation = [0, 0, 3]
            [goal]
            translation = [{hole_x}, 0, 30]
            [bounds]
            min = [-20, -20, -5]
            max = [20, 20, 40]
            [rotation]
            mode = "none"
            [planner]
            clearance = {clearance}
            time_limit = {time_limit}
            threads = 1
            """))
    return path


@pytest.fixture(scope="session")
def swept_cli():
    cli = os.environ.get("SWEPT_CLI")
    if not cli or not os.path.exists(cli):
        pytest.skip("SWEPT_CLI is not set (run through ctest)")
    return cli


@pytest.fixture(scope="session")
def py_reference():
    ref = os.environ.get("SWEPT_PY_REFERENCE")
    if not ref or not os.path.exists(ref):
        pytest.skip("SWEPT_PY_REFERENCE is not set (run through ctest)")
    return ref


def write_cup_assembly(folder, name="cupset", peg_bottom=0.0, lid=True):
    """A TOML assembly: a cup (floor z in [-2, 0] and four walls up to z = 10, 20 x 20 inside;
    fixed), a 4 x 4 peg standing on the floor at the centre (z in [peg_bottom, 6]) and a lid
    resting on the walls (z in [10, 12]). The peg's only way out is up, through the lid: the lid
    must come out first. peg_bottom < 0 sinks the peg into the floor (an interference)."""
    os.makedirs(folder, exist_ok=True)
    cup = merge(box((-12, -12, -2), (12, 12, 0)),
                box((-12, -12, 0), (-10, 12, 10)), box((10, -12, 0), (12, 12, 10)),
                box((-10, -12, 0), (10, -10, 10)), box((-10, 10, 0), (10, 12, 10)))
    write_stl(os.path.join(folder, f"{name}_cup.stl"), *cup, "cup")
    write_stl(os.path.join(folder, f"{name}_peg.stl"), *box((-2, -2, peg_bottom), (2, 2, 6)), "peg")
    text = f'unit = "mm"\n\n[[part]]\nfile = "{name}_cup.stl"\nname = "cup"\nfixed = true\n\n' \
           f'[[part]]\nfile = "{name}_peg.stl"\nname = "peg"\n'
    if lid:
        write_stl(os.path.join(folder, f"{name}_lid.stl"), *box((-12, -12, 0), (12, 12, 2)), "lid")
        # the lid's file is at z in [0, 2]: the pose puts it on the walls
        text += f'\n[[part]]\nfile = "{name}_lid.stl"\nname = "lid"\npose = {{ translation = [0, 0, 10] }}\n'
    path = os.path.join(folder, f"{name}.toml")
    with open(path, "w") as f:
        f.write(text)
    return path
