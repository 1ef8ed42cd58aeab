#!/usr/bin/env python3
"""Writes the hand-made seed corpora of fuzz/corpus/ and the meshes of fuzz/data/ that the
problem seeds name: a tetrahedron (and a unit cube) in every mesh format, problems, paths.
The CAD seeds (box.step, box.iges, box.brep) come from OpenCASCADE (see docs/reliability.md)
and are not written here. Run from anywhere: python3 fuzz/make_seeds.py"""
import base64
import json
import os
import struct
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
CORPUS = os.path.join(HERE, "corpus")
DATA = os.path.join(HERE, "data")

# A tetrahedron with outward faces (mm), and a cube of side 10 as 12 triangles.
TET_V = [(0, 0, 0), (10, 0, 0), (0, 10, 0), (0, 0, 10)]
TET_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
CUBE_V = [(x, y, z) for x in (0, 10) for y in (0, 10) for z in (0, 10)]
CUBE_F = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
          (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]


def write(folder, name, data):
    os.makedirs(folder, exist_ok=True)
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(os.path.join(folder, name), mode) as f:
        f.write(data)


def threemf(entries):
    """A 3MF package (a ZIP) of the given parts, stored uncompressed (mutations then reach the
    XML) and dated 1980-01-01 so that the bytes depend on the parts alone."""
    import io
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_STORED) as z:
        for name, text in entries:
            z.writestr(zipfile.ZipInfo(name, (1980, 1, 1, 0, 0, 0)), text)
    return buf.getvalue()


THREEMF_RELS = ('<?xml version="1.0" encoding="UTF-8"?>\n<Relationships xmlns="http://schemas.openxmlformats.org/'
                'package/2006/relationships"><Relationship Target="/3D/3dmodel.model" Id="r0" '
                'Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>\n')


def threemf_model(unit, resources, build):
    return ('<?xml version="1.0" encoding="UTF-8"?>\n<model xmlns="http://schemas.microsoft.com/3dmanufacturing/core/'
            '2015/02" xmlns:p="http://schemas.microsoft.com/3dmanufacturing/production/2015/06" unit="%s">\n'
            '<resources>\n%s</resources>\n<build>\n%s</build>\n</model>\n' % (unit, resources, build))


def threemf_object(oid, v, f):
    return ('<object id="%d" type="model"><mesh><vertices>\n' % oid +
            "".join('<vertex x="%g" y="%g" z="%g"/>\n' % p for p in v) + "</vertices><triangles>\n" +
            "".join('<triangle v1="%d" v2="%d" v3="%d"/>\n' % t for t in f) + "</triangles></mesh></object>\n")


def normal(v, f):
    a, b, c = (v[i] for i in f)
    u = [b[k] - a[k] for k in range(3)]
    w = [c[k] - a[k] for k in range(3)]
    n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
    s = sum(x * x for x in n) ** 0.5 or 1.0
    return [x / s for x in n]


def stl_ascii(v, f, name):
    out = [f"solid {name}"]
    for t in f:
        out.append("  facet normal %g %g %g" % tuple(normal(v, t)))
        out.append("    outer loop")
        out += ["      vertex %g %g %g" % v[i] for i in t]
        out += ["    endloop", "  endfacet"]
    out.append(f"endsolid {name}")
    return "\n".join(out) + "\n"


def stl_binary(v, f):
    out = b"binary tetrahedron".ljust(80, b" ") + struct.pack("<I", len(f))
    for t in f:
        out += struct.pack("<3f", *normal(v, t))
        for i in t:
            out += struct.pack("<3f", *v[i])
        out += b"\0\0"
    return out


def obj(v, f):
    return "# tetrahedron\no tet\n" + "".join("v %g %g %g\n" % p for p in v) + \
        "".join("f %d %d %d\n" % tuple(i + 1 for i in t) for t in f)


def off(v, f):
    return "OFF\n%d %d 0\n" % (len(v), len(f)) + "".join("%g %g %g\n" % p for p in v) + \
        "".join("3 %d %d %d\n" % t for t in f)


def ply_ascii(v, f):
    return ("ply\nformat ascii 1.0\ncomment tetrahedron\nelement vertex %d\nproperty float x\n"
            "property float y\nproperty float z\nelement face %d\nproperty list uchar int vertex_indices\n"
            "end_header\n" % (len(v), len(f))) + "".join("%g %g %g\n" % p for p in v) + \
        "".join("3 %d %d %d\n" % t for t in f)


def ply_binary(v, f):
    head = ("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
            "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
            % (len(v), len(f))).encode()
    body = b"".join(struct.pack("<3f", *p) for p in v) + b"".join(struct.pack("<B3i", 3, *t) for t in f)
    return head + body


def gltf_parts(v, f):
    """JSON document and binary buffer of a glTF 2.0 mesh (float positions, uint16 indices)."""
    pos = b"".join(struct.pack("<3f", *p) for p in v)
    idx = b"".join(struct.pack("<3H", *t) for t in f)
    idx += b"\0" * (-len(idx) % 4)
    doc = {
        "asset": {"version": "2.0", "generator": "swept fuzz/make_seeds.py"},
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "tet", "translation": [0, 0, 0]}],
        "meshes": [{"name": "tet", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
        "buffers": [{"byteLength": len(pos) + len(idx)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos), "target": 34962},
                        {"buffer": 0, "byteOffset": len(pos), "byteLength": 3 * 2 * len(f), "target": 34963}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(v), "type": "VEC3",
                       "min": [min(p[k] for p in v) for k in range(3)], "max": [max(p[k] for p in v) for k in range(3)]},
                      {"bufferView": 1, "componentType": 5123, "count": 3 * len(f), "type": "SCALAR"}],
    }
    return doc, pos + idx


def gltf(v, f):
    doc, buf = gltf_parts(v, f)
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(buf).decode()
    return json.dumps(doc, indent=1) + "\n"


def glb(v, f):
    doc, buf = gltf_parts(v, f)
    js = json.dumps(doc, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    chunks = struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(buf), 0x004E4942) + buf
    return b"glTF" + struct.pack("<II", 2, 12 + len(chunks)) + chunks


def dae(v, f, up="Z_UP", matrix=None):
    floats = " ".join("%g %g %g" % p for p in v)
    p = " ".join("%d %d %d" % t for t in f)
    node = '<matrix sid="transform">%s</matrix>' % matrix if matrix else ""
    return f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="millimeter" meter="0.001"/><up_axis>{up}</up_axis></asset>
  <library_geometries>
    <geometry id="tet" name="tet"><mesh>
      <source id="tet-pos"><float_array id="tet-pos-array" count="{3 * len(v)}">{floats}</float_array>
        <technique_common><accessor source="#tet-pos-array" count="{len(v)}" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <vertices id="tet-vtx"><input semantic="POSITION" source="#tet-pos"/></vertices>
      <triangles count="{len(f)}"><input semantic="VERTEX" source="#tet-vtx" offset="0"/><p>{p}</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="Scene" name="Scene">
    <node id="tet-node" name="tet">{node}<instance_geometry url="#tet"/></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#Scene"/></scene>
</COLLADA>
"""


def main():
    c = lambda t: os.path.join(CORPUS, "fuzz_" + t)
    write(c("stl"), "tet_ascii.stl", stl_ascii(TET_V, TET_F, "tet"))
    write(c("stl"), "tet_binary.stl", stl_binary(TET_V, TET_F))
    write(c("stl"), "two_solids.stl", stl_ascii(TET_V, TET_F, "a") + stl_ascii(CUBE_V, CUBE_F[:2], "b"))
    write(c("obj"), "tet.obj", obj(TET_V, TET_F))
    write(c("obj"), "cube_quads.obj", "o cube\n" + "".join("v %g %g %g\n" % p for p in CUBE_V) +
          "vn 0 0 1\nvt 0 0\nf 1/1/1 2/1/1 4/1/1 3/1/1\nf -4 -3 -1 -2\ng side\nf 1 5 6 2\n")
    write(c("ply"), "tet_ascii.ply", ply_ascii(TET_V, TET_F))
    write(c("ply"), "tet_binary.ply", ply_binary(TET_V, TET_F))
    write(c("off"), "tet.off", off(TET_V, TET_F))
    write(c("off"), "cube_quad.off", "OFF\n# a square\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
    # swept's own OFF reader: Geomview's header variants, comments anywhere, polygons to clip.
    write(c("off"), "l_shape_coff.off", "COFF 6 1 0 # an L\n0 0 0 255 0 0 #red\n3 0 0 0 0 255\n3 1 0 0.1 0.2 0.3\n"
          "1 1 0 1 1 1\n1 3 0 0 0 0\n0 3 0 0 0 0\n\n# the face\n6 0 1 2 3 4 5 255 0 0\n")
    write(c("off"), "homogeneous.off", "4nOFF 3\n4 2 0\n0 0 0 2\n2 0 0 2\n4 4 0 4\n0 3 0 3\n3 0 1 2\n3 0 2 3\n")
    write(c("3mf"), "tet.3mf", threemf([("_rels/.rels", THREEMF_RELS),
                                        ("3D/3dmodel.model", threemf_model("millimeter", threemf_object(1, TET_V, TET_F),
                                                                           '<item objectid="1"/>\n'))]))
    write(c("3mf"), "components.3mf", threemf([
        ("_rels/.rels", THREEMF_RELS),
        ("3D/3dmodel.model", threemf_model(
            "inch", '<object id="2" name="pair"><components>\n'
            '<component objectid="1" transform="0 1 0 -1 0 0 0 0 1 0 0 0"/>\n'
            '<component p:path="/3D/Objects/cube.model" objectid="1" transform="1 0 0 0 1 0 0 0 1 10 0 0"/>\n'
            '</components></object>\n' + threemf_object(1, TET_V, TET_F),
            '<item objectid="2" transform="1 0 0 0 1 0 0 0 1 0 0 5"/>\n')),
        ("3D/Objects/cube.model", threemf_model("inch", threemf_object(1, CUBE_V, CUBE_F), ""))]))
    write(c("gltf"), "tet.gltf", gltf(TET_V, TET_F))
    write(c("glb"), "tet.glb", glb(TET_V, TET_F))
    write(c("dae"), "tet_z_up.dae", dae(TET_V, TET_F))
    write(c("dae"), "tet_matrix_y_up.dae", dae(TET_V, TET_F, "Y_UP", "1 0 0 5 0 1 0 0 0 0 1 0 0 0 0 1"))

    # Meshes the problem seeds name; copied beside each problem input by the targets.
    write(DATA, "tet.stl", stl_ascii(TET_V, TET_F, "tet"))
    write(DATA, "cube.stl", stl_binary(CUBE_V, CUBE_F))
    write(DATA, "tet.obj", obj(TET_V, TET_F))
    write(DATA, "tet.off", off(TET_V, TET_F))
    write(DATA, "tet.dae", dae(TET_V, TET_F))

    write(c("problem_toml"), "full.toml", """unit = "mm"
[[obstacle]]
file = "cube.stl"
file_unit = "mm"
deflection = 0.1
pose = { translation = [0, 0, 0], axis = [0, 0, 1], angle_deg = 0 }
[[body]]
file = "tet.obj"
pose = { translation = [20, 0, 0] }
[body_frame]
reference_point = [2.5, 2.5, 2.5]
[start]
translation = [0, 0, 0]
quaternion = [0, 0, 0, 1]
[goal]
translation = [0, 0, 500]
quaternion = [0, 0, 0, 1]
[bounds]
min = [-500, -500, -500]
max = [500, 500, 1000]
[rotation]
mode = "limits"
limits_deg = [[-30, 30], [-30, 30], [-180, 180]]
[planner]
clearance = 0.5
contact_tolerance = 0.0
fitter = "inertia"
time_limit = 60.0
deflection = 0.1
threads = 2
""")
    write(c("problem_toml"), "outside.toml", """unit = "in"
[[obstacle]]
file = "box.brep"
[[obstacle]]
file = "tet.dae"
file_unit = "m"
[[body]]
file = "tet.stl"
pose = { translation = [1, 2, 3], quaternion = [0, 0, 1e300, 1e300] }
[start]
translation = [0, 0, 30]
axis = [1, 0, 0]
angle_deg = 90
[goal]
outside = true
margin = 10.0
[rotation]
mode = "none"
[planner]
fitter = "pqp"
""")
    write(c("problem_cfg"), "tet_cube.cfg", """[problem]
robot = tet.stl
world = cube.stl
start.x = 0
start.y = 0
start.z = 30
start.theta = 0.5
start.axis.x = 0
start.axis.y = 0
start.axis.z = 1
goal.x = 0
goal.y = 0
goal.z = 200
goal.theta = 0
volume.min.x = -300
volume.min.y = -300
volume.min.z = -300
volume.max.x = 300
volume.max.y = 300
volume.max.z = 300
[solver]
planner = rrtconnect  ; keys outside [problem] are ignored
""")
    write(c("problem_cfg"), "dae_robot.cfg", """# OMPL.app problem with a COLLADA robot
[problem]
robot = tet.dae
world = tet.off
start.x = 1.5
start.y = -2
start.z = 3e1
goal.x = 0
goal.y = 0
goal.z = 100
goal.theta = 3.14159
goal.axis.x = 1
goal.axis.y = 1
goal.axis.z = 0
""")
    write(c("problem_cfg"), "obj_robot.cfg", "[problem]\nrobot = tet.obj\nworld = tet.stl\n"
          "start.x = 0\nstart.y = 0\nstart.z = 0\ngoal.x = 1\ngoal.y = 2\ngoal.z = 3\n")

    poses = [{"translation": [0, 0, 0], "quaternion": [0, 0, 0, 1]},
             {"translation": [0, 0, 10.5], "quaternion": [0, 0, 0.38268343236508978, 0.92387953251128674]},
             {"translation": [1e-3, -2, 3e2], "quaternion": [1, 0, 0, 0]}]
    write(c("path_json"), "three_poses.json", json.dumps(
        {"unit": "mm", "reference_point": [2.5, 2.5, 2.5], "poses": poses}, indent=1) + "\n")
    write(c("path_json"), "one_pose.json", '{"unit":"m","reference_point":[0,0,0],"poses":[{"translation":[1,2,3],"quaternion":[0,0,0,2]}]}\n')
    write(c("path_ompl"), "three_poses.path", "0 0 0 0 0 0 1\n0 0 10.5 0 0 0.38268343236508978 0.92387953251128674\n"
          "\n0.001 -2 300 1 0 0 0\n")
    write(c("path_ompl"), "spaced.path", "  1e2\t-3.5 0 0 0 1e-300 1e-300 \r\n")
    # OMPL's PathGeometric::print() form, as OMPL.app ships its resources/3D/*.path.
    write(c("path_ompl"), "printed.path", "Compound state [\nRealVectorState [270 160 -200]\nSO3State [0 0 0 1]\n]\n"
          "Compound state [\nRealVectorState [1e-3 -2 300]\nSO3State [6.12323e-17 1 6.12323e-17 3.7494e-33]\n]\n")


if __name__ == "__main__":
    main()
