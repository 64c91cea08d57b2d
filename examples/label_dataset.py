#!/usr/bin/env python3
"""Labels N configurations of a robot over M scenes on a Dask cluster: for
every (scene, configuration) pair whether the robot touches the map
(collided), its minimum distance to the map (m, padding included, 0 when
touching), and for every configuration whether it touches itself
(self_collided).

    label_dataset.py [--configurations N] [--scenes M] [--map FILE ...]
                     [--scheduler tcp://HOST:8786 | --workers K]
                     [--chunk C] [--out FILE.npz|FILE.parquet] [--check-serial]

The robot is a 7-joint arm of cylinders (generated URDF text, no mesh
files), its configurations drawn uniformly in its joint limits (--seed).
Scenes: M generated clutter maps (random points at 5 cm, one seed each) and
every --map file (.bt, .ot or .opx), the arm's base at the map origin.

Maps travel to the workers pickled (an Octree pickles as its .opx bytes),
once per worker; the robot travels as its URDF text, rebuilt once per
worker.  Each task labels one chunk of configurations in one batch call
(Query.check_configurations).  Without --scheduler a local cluster of
--workers processes (one thread each) runs on this machine.

Output (--out): five equal-length columns, one row per (scene,
configuration): scene, configuration, collided, self_collided, distance; a
.parquet file where pyarrow is installed, else a .npz of numpy arrays.
--check-serial labels everything again in this process and fails unless
the cluster's labels are the same bit for bit.

Exit status: 0 done, 1 the serial check failed, 2 bad arguments (or a
.parquet name without pyarrow), 77 dask.distributed is not installed
(Debian: python3-distributed).
"""
import argparse
import sys
import time

import numpy as np

import octoprox

JOINTS = 7
COLUMNS = ("scene", "configuration", "collided", "self_collided", "distance")


def arm_urdf():
    """Links l0..l7, each a cylinder 0.04 to 0.2 m along its z, joints
    alternating z and y axes 0.24 m apart (the Python tests' arm)."""
    links, joints = [], []
    for k in range(JOINTS + 1):
        links.append(
            f'<link name="l{k}"><collision><origin xyz="0 0 0.12"/><geometry>'
            f'<cylinder radius="0.035" length="0.16"/></geometry></collision></link>')
        if k > 0:
            axis = "0 0 1" if k % 2 else "0 1 0"
            joints.append(
                f'<joint name="j{k}" type="revolute"><parent link="l{k - 1}"/><child link="l{k}"/>'
                f'<origin xyz="0 0 {0.1 if k == 1 else 0.24}"/><axis xyz="{axis}"/>'
                f'<limit lower="-3.14" upper="3.14" effort="1" velocity="1"/></joint>')
    return '<robot name="arm">' + "".join(links + joints) + "</robot>"


class Robot:
    """A link set that pickles as its URDF text and the link pairs that
    self-collision skips: a worker unpickles it once and rebuilds the link
    set there (a LinkSet itself does not pickle).  The link set is only
    read by the batch calls, so the tasks of one worker's threads share
    it."""

    def __init__(self, urdf, disabled_pairs=()):
        self.urdf, self.disabled_pairs = urdf, tuple(disabled_pairs)
        self.links = octoprox.LinkSet.from_urdf_string(urdf)
        for a, b in self.disabled_pairs:
            self.links.set_pair_enabled(a, b, False)

    def __getstate__(self):
        return {"urdf": self.urdf, "disabled_pairs": self.disabled_pairs}

    def __setstate__(self, state):
        self.__init__(state["urdf"], state["disabled_pairs"])


def generated_map(seed):
    """A room of clutter: 400 points in 3 x 3 x 2 m around the arm, 5 cm."""
    rng = np.random.default_rng(seed)
    points = np.column_stack([rng.uniform(-1.5, 1.5, 400), rng.uniform(-1.5, 1.5, 400),
                              rng.uniform(0.0, 2.0, 400)])
    tree = octoprox.Octree(resolution=0.05)
    tree.insert_points(points, mode=octoprox.INSERT_ENDPOINTS)
    return tree


def configurations(n, seed):
    return np.random.default_rng(seed).uniform(-3.1, 3.1, size=(n, JOINTS))


def label_scene(tree, robot, q):
    """collided and distance of the rows q against one map."""
    collided, distance = octoprox.Query().check_configurations(tree, robot.links, q,
                                                               distance=True)
    return collided, distance


def label_self(robot, q):
    """self_collided of the rows q: against an empty map, self pairs on."""
    return octoprox.Query().check_configurations(octoprox.Octree(resolution=0.05), robot.links,
                                                 q, self_collision=True)


def chunks(n, size):
    return [(start, min(start + size, n)) for start in range(0, n, size)]


def assemble(q_count, scene_count, scene_parts, self_parts):
    """The rows, scene-major: scene_parts[(scene, start)] = (collided,
    distance), self_parts[start] = self_collided."""
    self_collided = np.concatenate([self_parts[k] for k in sorted(self_parts)])
    collided, distance = [], []
    for scene in range(scene_count):
        starts = sorted(start for (s, start) in scene_parts if s == scene)
        collided += [scene_parts[(scene, start)][0] for start in starts]
        distance += [scene_parts[(scene, start)][1] for start in starts]
    return {
        "scene": np.repeat(np.arange(scene_count, dtype=np.int32), q_count),
        "configuration": np.tile(np.arange(q_count, dtype=np.int64), scene_count),
        "collided": np.concatenate(collided),
        "self_collided": np.tile(self_collided, scene_count),
        "distance": np.concatenate(distance),
    }


def label_serial(maps, robot, q, chunk):
    spans = chunks(len(q), chunk)
    scene_parts = {(i, a): label_scene(tree, robot, q[a:b])
                   for i, tree in enumerate(maps) for a, b in spans}
    self_parts = {a: label_self(robot, q[a:b]) for a, b in spans}
    return assemble(len(q), len(maps), scene_parts, self_parts)


def label_cluster(client, maps, robot, q, chunk, progress):
    """One task per (scene, chunk) and per chunk for self-collision; the
    maps and the robot scattered to every worker once."""
    map_futures = client.scatter(maps, broadcast=True)
    robot_future = client.scatter(robot, broadcast=True)
    spans = chunks(len(q), chunk)
    # Each chunk of rows travels once, not once per scene.
    rows = dict(zip((a for a, _ in spans), client.scatter([q[a:b] for a, b in spans])))
    scene_tasks = {(i, a): client.submit(label_scene, tree, robot_future, rows[a], pure=False)
                   for i, tree in enumerate(map_futures) for a, _ in spans}
    self_tasks = {a: client.submit(label_self, robot_future, rows[a], pure=False)
                  for a, _ in spans}
    every = list(scene_tasks.values()) + list(self_tasks.values())
    if progress:
        from distributed import progress as progress_bar
        progress_bar(every)
        print()
    scene_parts = dict(zip(scene_tasks, client.gather(list(scene_tasks.values()))))
    self_parts = dict(zip(self_tasks, client.gather(list(self_tasks.values()))))
    return assemble(len(q), len(maps), scene_parts, self_parts)


def same_bits(a, b):
    return all(a[c].dtype == b[c].dtype and a[c].tobytes() == b[c].tobytes() for c in COLUMNS)


def writer(path):
    """A function writing the rows to path: Parquet for a .parquet name,
    else .npz; exits (status 2) before any work when a .parquet name
    finds no pyarrow."""
    if not path.endswith(".parquet"):
        return lambda rows: np.savez(path, **rows)
    try:
        import pyarrow
        import pyarrow.parquet
    except ImportError:
        print(f"label_dataset: {path}: writing Parquet needs pyarrow; "
              "give a .npz name instead", file=sys.stderr)
        sys.exit(2)
    return lambda rows: pyarrow.parquet.write_table(
        pyarrow.table({c: rows[c] for c in COLUMNS}), path)


def parse():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--configurations", type=int, default=20000, metavar="N")
    parser.add_argument("--scenes", type=int, default=4, metavar="M",
                        help="generated clutter maps (besides --map files)")
    parser.add_argument("--map", action="append", default=[], metavar="FILE",
                        help="a map file as one more scene (.bt, .ot, .opx)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--chunk", type=int, default=1000,
                        help="configurations per task (one batch call)")
    parser.add_argument("--scheduler", metavar="tcp://HOST:8786",
                        help="a running scheduler (default: a local cluster)")
    parser.add_argument("--workers", type=int, default=2,
                        help="worker processes of the local cluster")
    parser.add_argument("--out", metavar="FILE", help=".npz, or .parquet with pyarrow")
    parser.add_argument("--no-progress", action="store_true")
    parser.add_argument("--check-serial", action="store_true",
                        help="label again in this process and compare bit for bit")
    args = parser.parse_args()
    for name in ("configurations", "chunk", "workers"):
        if getattr(args, name) < 1:
            parser.error(f"--{name} must be at least 1")
    if args.scenes < 0 or args.scenes + len(args.map) < 1:
        parser.error("no scene: give --scenes 1 or more, or a --map")
    return args


def main():
    args = parse()
    try:
        from distributed import Client, LocalCluster
    except ImportError:
        print("label_dataset: skipped: dask.distributed is not installed "
              "(Debian: python3-distributed; scripts/setup installs it)")
        return 77
    write = writer(args.out) if args.out else None
    maps = [generated_map(args.seed * 1000 + i) for i in range(args.scenes)]
    maps += [octoprox.Octree.load(path) for path in args.map]
    # l1's cylinder overlaps l0's at every angle: the pair an SRDF would
    # mark adjacent.
    robot = Robot(arm_urdf(), [("l0", "l1")])
    q = configurations(args.configurations, args.seed)
    if args.scheduler:
        cluster, client = None, Client(args.scheduler)
    else:
        # Loopback only: a local cluster needs no network.
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                               host="127.0.0.1", dashboard_address=None)
        client = Client(cluster)
    try:
        workers = len(client.scheduler_info()["workers"])
        start = time.perf_counter()
        rows = label_cluster(client, maps, robot, q, args.chunk, not args.no_progress)
        seconds = time.perf_counter() - start
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    pairs = len(q) * len(maps)
    print(f"labelled {len(q)} configurations x {len(maps)} scenes on {workers} workers "
          f"in {seconds:.2f} s: {pairs / seconds:.0f} (scene, configuration) pairs/s; "
          f"{int(rows['collided'].sum())} collided, {int(rows['self_collided'].sum()) // max(len(maps), 1)} "
          f"configurations self-collided")
    if write:
        write(rows)
        print(f"wrote {args.out}")
    if args.check_serial:
        start = time.perf_counter()
        serial = label_serial(maps, robot, q, args.chunk)
        seconds = time.perf_counter() - start
        if not same_bits(rows, serial):
            print("serial check: FAILED, the cluster's labels differ from this process's")
            return 1
        print(f"serial check: the same bit for bit ({seconds:.2f} s in this process)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
