"""swept: exact distance and collision queries between rigid triangle meshes (RSS trees), and the
certified, deterministic 6-DOF disassembly planner, from Python with NumPy arrays.

    import numpy as np, swept
    a = swept.Mesh.load("frame.stl")
    b = swept.Mesh.load("part.step", deflection=0.05)
    ta, tb = swept.BVH(a), swept.BVH(b, fitter="inertia")
    poses = np.zeros((1000, 7)); poses[:, 6] = 1; poses[:, 2] = np.linspace(10, 100, 1000)
    r = swept.distance(ta, tb, None, poses)         # r.distance (1000,), r.point_a (1000, 3), ...
    res = swept.plan(swept.Problem.load("problem.toml"), time_limit=30)
    res.path                                        # (P, 7): x, y, z, qx, qy, qz, qw
    seq = swept.disassemble("gearbox.toml")         # seq.complete, seq.sequence[k].parts, .path

Poses are arrays of shape (7,) or (K, 7) -- translation then quaternion (x, y, z, qx, qy, qz, qw),
scalar last as in OMPL's .path files, not necessarily normalised -- or (4, 4) / (K, 4, 4)
homogeneous matrices; None is the identity. A single pose is used for every K.

Bad input raises swept.Error (a ValueError) with the message the command line prints. The
queries release the GIL and spread a batch over threads (`threads=0`: all cores). See
docs/python.md.
"""
from __future__ import annotations

import os
from typing import Any, NamedTuple, Optional

import numpy as np

from ._swept import BVH, Assembly, Error, Mesh, Problem, Scene, __version__
from . import _swept

for _cls in (BVH, Assembly, Error, Mesh, Problem, Scene):
    _cls.__module__ = "swept"  # swept.Error in tracebacks, not swept._swept.Error
del _cls

__all__ = [
    "Assembly", "BVH", "Error", "Mesh", "Problem", "Scene", "PlanResult",
    "DistanceResult", "CollideResult", "ToleranceResult", "MotionResult",
    "DisassemblyResult", "DisassemblyStep", "Interference",
    "distance", "collide", "tolerance", "motion_clearance", "plan", "disassemble", "__version__",
]


class DistanceResult(NamedTuple):
    """Per pose k: the exact distance between the meshes, the closest points (world frame), the
    input indices of the two closest triangles, and the work done."""
    distance: np.ndarray        #: (K,) float64
    point_a: np.ndarray         #: (K, 3) float64, on A, world frame
    point_b: np.ndarray         #: (K, 3) float64, on B, world frame
    triangle_a: np.ndarray      #: (K,) int64, index into A's faces
    triangle_b: np.ndarray      #: (K,) int64
    exact: np.ndarray           #: (K,) bool (False only with rel_err/abs_err early exits)
    bv_tests: np.ndarray        #: (K,) uint64 RSS-pair tests
    triangle_tests: np.ndarray  #: (K,) uint64 triangle-pair tests


class CollideResult(NamedTuple):
    """Per pose k: whether the meshes intersect, the first intersecting triangle pair (-1 when
    none), and with all_contacts=True a list of (n_k, 2) arrays of every intersecting pair."""
    colliding: np.ndarray       #: (K,) bool
    triangle_a: np.ndarray      #: (K,) int64, -1 when not colliding
    triangle_b: np.ndarray      #: (K,) int64
    bv_tests: np.ndarray
    triangle_tests: np.ndarray
    contacts: Optional[list]    #: all_contacts: K arrays (n_k, 2) int64, sorted; else None


class ToleranceResult(NamedTuple):
    """Per pose k: whether the distance is below the tolerance and, when it is, a witness pair
    (distance, points, triangles; -1 and inf otherwise)."""
    within: np.ndarray          #: (K,) bool
    distance: np.ndarray        #: (K,) float64, the witness pair's distance when within, else inf
    point_a: np.ndarray         #: (K, 3)
    point_b: np.ndarray         #: (K, 3)
    triangle_a: np.ndarray      #: (K,) int64, -1 when not within
    triangle_b: np.ndarray      #: (K,) int64
    bv_tests: np.ndarray
    triangle_tests: np.ndarray


class MotionResult(NamedTuple):
    """Per motion k (B from poses_from[k] to poses_to[k], A at poses_a[k]): certified free with
    distance >= margin along the whole continuous motion, or where it was blocked."""
    free: np.ndarray                #: (K,) bool, certified
    t_blocked: np.ndarray           #: (K,) float64, motion parameter where blocked (-1 when free)
    distance_at_block: np.ndarray   #: (K,) float64
    min_distance: np.ndarray        #: (K,) float64, smallest distance bound seen
    distance_queries: np.ndarray    #: (K,) int64
    sweeps: np.ndarray              #: (K,) int64, exact sweeps of a grazing translation (0 or 1)
    reference: np.ndarray           #: (3,) the body-frame point the motion interpolates about
    radius: float                   #: B's radius about the reference


class PlanResult(NamedTuple):
    """What swept.plan() found: the fields of `swept plan --json`, and the path as an array."""
    status: str                 #: solved | no_path_time | no_path_budget | no_path_bounds | no_path_resolution
    solved: bool
    message: str
    path: np.ndarray            #: (P, 7) x, y, z, qx, qy, qz, qw of the body frame, start ... goal
    path_length: float          #: sum of ||delta c|| + r_max * theta
    translation_length: float
    rotation_length_rad: float
    min_clearance: Optional[float]  #: None when not solved
    escape: Optional[dict]      #: a start in contact: {"segments": 1 or 2} pulls out, by the mate rule
    approach: Optional[dict]    #: a goal in contact: {"segments": 1 or 2} pulls in, by the mate rule
    time_ms: dict               #: build, search, smooth, total
    queries: dict               #: distance, tolerance, collide
    path_hash: str              #: 16 hex digits, as `swept plan` prints
    seed: int                   #: the draw of the trees' samples planned with
    unit: str
    fitter: str
    level: int
    nodes_checked: int
    edges_checked: int
    reference_point: np.ndarray  #: (3,) body frame

    @property
    def waypoints(self) -> int:
        return int(self.path.shape[0])


class Interference(NamedTuple):
    """Two parts overlapping by more than the mating tolerance where they are mounted."""
    parts: tuple                #: (name_a, name_b), in the assembly's order
    depth: float                #: the deepest intersecting triangle pair's overlap
    extent: float               #: diagonal of the box of the crossing points
    triangle_pairs: int         #: intersecting triangle pairs deeper than the tolerance


class DisassemblyStep(NamedTuple):
    """One entry of a disassembly sequence: a removal (a part, or a group of touching parts moving
    as one) or, at the end, a part that stays with what blocks it."""
    round: int                  #: 1-based; blocked parts: the last round
    parts: tuple                #: the part's name, or the group's names
    removed: bool
    method: Optional[str]       #: "pull" (straight) | "plan" (the planner); None when blocked
    direction: Optional[np.ndarray]  #: (3,) unit direction of a pull, else None
    distance: float             #: how far a pull goes (to outside the remaining parts' box)
    path: np.ndarray            #: (P, 7) poses of the part's frame (identity = mounted), x, y, z, qx, qy, qz, qw
    reference: np.ndarray       #: (3,) the point the path's rotations interpolate about
    blockers: tuple             #: blocked: every part that blocks some direction on its own
    blocking: list              #: blocked: (direction (3,), blocker names) per direction tried
    time_ms: float              #: time of the round's attempts on this part (varies run to run)


class DisassemblyResult(NamedTuple):
    """What swept.disassemble() found: the fields of `swept disassemble --json`."""
    complete: bool              #: every movable part comes out
    unit: str
    parts: tuple                #: every part's name, in the assembly's order
    fixed: tuple                #: the parts never moved
    clearance: float
    tolerance: float            #: the mating tolerance used
    interferences: list         #: [Interference], checked first
    sequence: list              #: [DisassemblyStep]: removals in order, then the parts that stay
    warnings: list
    time_ms: dict               #: build, interference, sequence
    distance_queries: int
    targets: tuple              #: target=...: the targets' names (empty: the whole assembly)
    fewest: bool                #: target=...: no smaller set of removals frees them
    lower_bound: int            #: target=...: no set of fewer removals frees them
    why: list                   #: target=...: [DisassemblyStep] of the targets and the parts removed for them, with .blocking

    @property
    def order(self) -> list:
        """The removed parts' names in removal order (a group's names together)."""
        return [n for s in self.sequence if s.removed for n in s.parts]


def _check_tree(t: Any, name: str) -> None:
    if not isinstance(t, BVH):
        raise TypeError(f"{name}: a swept.BVH is needed, not {type(t).__name__}")


def distance(a: BVH, b: BVH, poses_a: Any = None, poses_b: Any = None, *, rel_err: float = 0.0,
             abs_err: float = 0.0, threads: int = 0) -> DistanceResult:
    """Exact distance between mesh A at poses_a[k] and mesh B at poses_b[k], for every k.

    poses_a, poses_b: None (identity), one pose (7,) / (4, 4), or K poses (K, 7) / (K, 4, 4);
    a single pose is used for every k. rel_err / abs_err: stop once the answer is provably within
    this relative / absolute error (PQP semantics; 0: exact). threads: 0 all cores, 1 serial; the
    results do not depend on it. The GIL is released while the batch runs."""
    _check_tree(a, "a"), _check_tree(b, "b")
    return DistanceResult(**_swept._distance(a, b, poses_a, poses_b, rel_err, abs_err, threads))


def collide(a: BVH, b: BVH, poses_a: Any = None, poses_b: Any = None, *, all_contacts: bool = False,
            threads: int = 0) -> CollideResult:
    """Do mesh A at poses_a[k] and mesh B at poses_b[k] intersect (any triangle pair)?
    all_contacts=True also lists every intersecting triangle pair per pose."""
    _check_tree(a, "a"), _check_tree(b, "b")
    return CollideResult(**_swept._collide(a, b, poses_a, poses_b, all_contacts, threads))


def tolerance(a: BVH, b: BVH, poses_a: Any = None, poses_b: Any = None, tolerance: float = 0.0, *,
              threads: int = 0) -> ToleranceResult:
    """Is the distance between A at poses_a[k] and B at poses_b[k] below `tolerance`?"""
    _check_tree(a, "a"), _check_tree(b, "b")
    return ToleranceResult(**_swept._tolerance(a, b, poses_a, poses_b, tolerance, threads))


def motion_clearance(a: BVH, b: BVH, poses_a: Any, poses_from: Any, poses_to: Any, *, margin: float = 0.0,
                     reference: Any = None, radius: Optional[float] = None, max_queries: int = 200000,
                     threads: int = 0) -> MotionResult:
    """Certified motion clearance (Schwarzer, Saha, Latombe 2005): does B, moving from
    poses_from[k] to poses_to[k] (reference point linear, rotation slerped about it), keep a
    distance >= margin from A at poses_a[k] along the whole continuous motion? Never says free
    when it is not. reference: B's body-frame point (3,) the motion interpolates about (default:
    the centre of B's bounding box, as the planner); radius: B's radius about it (default:
    computed; a smaller one is refused). A translation that grazes the margin (more than
    64 bisection queries) is decided by the exact sweep of the translation (`sweeps`)."""
    _check_tree(a, "a"), _check_tree(b, "b")
    return MotionResult(**_swept._motion_clearance(a, b, poses_a, poses_from, poses_to, margin, reference, radius,
                                                   max_queries, threads))


def plan(problem: Problem, time_limit: Optional[float] = None, threads: Optional[int] = None, *,
         scene: Optional[Scene] = None, max_queries: Optional[int] = None, seed: Optional[int] = None) -> PlanResult:
    """Plans a certified path for the problem's body, as `swept plan` does.

    time_limit, threads: override the problem's (seconds; 0 threads: all cores; the path is the
    same at any count while the time limit is not reached). scene: a swept.Scene loaded for this
    problem file (reused: no mesh loading or tree building); default: loaded here with the
    problem's fitter. max_queries: stop after this many distance queries (status
    no_path_budget): a limit on the work that, unlike time_limit, ends the same way on every
    machine and at any thread count. seed: which draw of the trees' sample sequence (default: the
    problem's `seed`, else 0; docs/problem-format.md, planner.seed): another seed, another path
    where the trees solve the problem, the same path for the same seed. Not finding a path is a
    result (solved False, status and message saying which limit); bad input (start or goal
    outside the bounds or in collision, bad bounds) raises swept.Error with `swept plan`'s
    message. The GIL is released while planning."""
    if not isinstance(problem, Problem):
        raise TypeError(f"problem: a swept.Problem is needed, not {type(problem).__name__}")
    if scene is not None and not isinstance(scene, Scene):
        raise TypeError(f"scene: a swept.Scene is needed, not {type(scene).__name__}")
    return PlanResult(**_swept._plan(problem, time_limit, threads, scene, max_queries, seed))


def disassemble(assembly: "Assembly | str | os.PathLike", *, clearance: float = 0.01,
                tolerance: Optional[float] = None, jobs: int = 0, plan_time: float = 60.0,
                plan_queries: int = 20000, subassemblies: bool = True,
                fixed: Optional[Any] = None, target: Optional[Any] = None) -> DisassemblyResult:
    """Takes a whole assembly apart, as `swept disassemble` does (docs/assembly.md).

    assembly: a swept.Assembly, or a path read with Assembly.load(path) (TOML assembly file,
    folder of placed meshes, STEP / IGES / BREP with several solids). Interferences are reported
    first; then, round by round, one part (or group of touching parts) leaves by a certified
    straight pull -- the planner when none is clear (plan_queries distance queries per attempt,
    the same limit on every machine, 0: none; plan_time seconds, a safety net; 0: never plan) --
    and the parts that stay are reported with their blockers. clearance: every pair that is not
    a mate keeps more than this; tolerance: how far mated faces may overlap, and the interference
    threshold (default: twice the assembly's deflection). jobs: threads (0: all cores; the same
    result at any count). fixed: part names or indices never moved (default: the parts marked
    fixed, else the largest). target: part names or indices to take out with the fewest others
    that must come off first, by straight pulls (`swept disassemble --target`); the others stay
    mounted, and `why` says what blocks each direction. Parts that stay are a result (complete
    False), not an error; bad input raises swept.Error. The GIL is released while it runs."""
    if not isinstance(assembly, Assembly):
        if not isinstance(assembly, (str, os.PathLike)):
            raise TypeError(f"assembly: a swept.Assembly or a path is needed, not {type(assembly).__name__}")
        assembly = Assembly.load(assembly)
    if fixed is not None and isinstance(fixed, (str, int)):
        fixed = [fixed]
    if target is not None and isinstance(target, (str, int)):
        target = [target]
    d = _swept._disassemble(assembly, clearance, tolerance, jobs, plan_time, plan_queries, subassemblies,
                            None if fixed is None else list(fixed), None if target is None else list(target))
    d["interferences"] = [Interference(**f) for f in d["interferences"]]
    d["sequence"] = [DisassemblyStep(**s) for s in d["sequence"]]
    d["why"] = [DisassemblyStep(**s) for s in d["why"]]
    return DisassemblyResult(**d)
