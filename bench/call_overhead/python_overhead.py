#!/usr/bin/env python3
"""The per-call time of a tiny collision query from C and from Python.

The scene of the tests: one occupied 25 cm cell and a 10 cm sphere
touching it; every call answers "collided" after one exact test, so the
time is the library's fixed cost per query plus the caller's.  Rounds
interleave the C program (opx-bench-call-overhead, its own process) and
the Python calls in this process; each figure is the median of the rounds,
in CPU time of the calling thread (other programs' load on the machine
counts only through the caches).
Python is timed two ways: octoprox.Query.collide as users call it, and the
bare ctypes call of opx_query_collide with everything prepared (what no
binding built on ctypes can go below).  Rust is not measured: the Rust
bindings have no benchmark program.

    python_overhead.py [--quick] [--calls N] [--rounds R] [--c-program PATH] [--json FILE]

Run from anywhere after a build: the build tree's library and program are
found through $OPX_BUILD_DIR (default: build/ in the repository).  Prints
the CPU and a table; exits 77 when numpy or the program is missing.
"""
import argparse
import ctypes
import json
import os
import platform
import statistics
import subprocess
import sys
import time

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BUILD = os.environ.get("OPX_BUILD_DIR") or os.path.join(REPO, "build")
CELL, CENTRE = 0.25, 0.125


def parse():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="smoke run: 2,000 calls, 1 round")
    parser.add_argument("--calls", type=int, default=200000, help="calls per round (200000)")
    parser.add_argument("--rounds", type=int, default=7, help="rounds (7)")
    parser.add_argument("--c-program", default=os.path.join(
        BUILD, "bench", "call_overhead", "opx-bench-call-overhead"))
    parser.add_argument("--json", help="also write the figures to this file")
    args = parser.parse_args()
    if args.quick:
        args.calls, args.rounds = 2000, 1
    return args


def import_octoprox():
    """The package of this repository, with the build tree's library
    unless $OPX_LIBRARY names one."""
    library = os.path.join(BUILD, "src", "liboctoprox.so")
    if "OPX_LIBRARY" not in os.environ and os.path.exists(library):
        os.environ["OPX_LIBRARY"] = library
    sys.path.insert(0, os.path.join(REPO, "bindings", "python"))
    import octoprox
    return octoprox


def cpu_name():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def scene(octoprox):
    tree = octoprox.Octree(resolution=CELL)
    tree.insert_points([[CENTRE, CENTRE, CENTRE]], mode="endpoints")
    links = octoprox.LinkSet()
    links.add_sphere(links.add_link("ball"), 0.1)
    links.set_poses([[0.35, CENTRE, CENTRE]])
    return tree, links


class PythonCallers:
    """The two Python callers on the scene, each a loop timing `calls`
    calls as a user's loop makes them (ns per call, thread CPU time)."""

    def __init__(self, octoprox):
        from octoprox import _library
        self.tree, self.links = scene(octoprox)
        self.query = octoprox.Query()
        self.bare = _library.unchecked("opx_query_collide")
        self.result = octoprox.CollisionResult(ctypes.sizeof(octoprox.CollisionResult))
        assert self.query.collide(self.tree, self.links).collided
        assert self.bare(self.query._raw, self.tree._raw, self.links._raw, None, self.result) == 0
        assert self.result.collided

    def python_query_collide(self, calls):
        collide, tree, links = self.query.collide, self.tree, self.links
        start = time.thread_time_ns()
        for _ in range(calls):
            collide(tree, links)
        return (time.thread_time_ns() - start) / calls

    def python_ctypes_call(self, calls):
        bare, result = self.bare, self.result
        query, tree, links = self.query._raw, self.tree._raw, self.links._raw
        start = time.thread_time_ns()
        for _ in range(calls):
            bare(query, tree, links, None, result)
        return (time.thread_time_ns() - start) / calls


def c_round(program, calls):
    run = subprocess.run([program, "--calls", str(calls), "--rounds", "1"], capture_output=True,
                         text=True, check=True)
    return float(run.stdout.split()[-1])


def measure(args, octoprox):
    callers = PythonCallers(octoprox)
    names = ("python_ctypes_call", "python_query_collide")
    rounds = {name: [] for name in ("c",) + names}
    for name in names:
        getattr(callers, name)(max(1, args.calls // 10))  # warm-up
    for _ in range(args.rounds):
        rounds["c"].append(c_round(args.c_program, args.calls))
        for name in names:
            rounds[name].append(getattr(callers, name)(args.calls))
    return {name: statistics.median(values) for name, values in rounds.items()}


def report(figures, args):
    c = figures["c"]
    rows = [("C, opx_query_collide", "c"), ("Python, the bare ctypes call", "python_ctypes_call"),
            ("Python, Query.collide", "python_query_collide")]
    print(f"CPU: {cpu_name()}")
    print(f"Python {platform.python_version()}; median of {args.rounds} rounds of "
          f"{args.calls} calls; load average {os.getloadavg()[0]:.2f}")
    print("| caller | us per call | over C |")
    print("| --- | --- | --- |")
    for label, key in rows:
        print(f"| {label} | {figures[key] / 1000:.2f} | {figures[key] / c:.2f}x |")


def main():
    args = parse()
    if not os.path.exists(args.c_program):
        print(f"python_overhead: skipped: {args.c_program} not found (build opx-bench-call-overhead)")
        return 77
    try:
        octoprox = import_octoprox()
    except ImportError as error:
        print(f"python_overhead: skipped: the octoprox package cannot be imported ({error})")
        return 77
    figures = measure(args, octoprox)
    report(figures, args)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(dict(figures, cpu=cpu_name(), python=platform.python_version(),
                           calls=args.calls, rounds=args.rounds, unit="ns per call"), f, indent=1)
            f.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
