#!/usr/bin/env python3
"""The per-call time of a tiny collision query from C, Rust and Python.

The scene of the tests: one occupied 25 cm cell and a 10 cm sphere
touching it; every call answers "collided" after one exact test, so the
time is the library's fixed cost per query plus the caller's.  Rounds
interleave the C program (opx-bench-call-overhead), the Rust program (the
safe crate's example call_overhead, each in its own process) and the
Python calls in this process; each figure is the median of the rounds, in
CPU time of the calling thread (other programs' load on the machine counts
only through the caches).
Python is timed four ways: octoprox.Query.collide as users call it (with
the compiled call path octoprox._fastcall when the package finds it), the
same with a keyword (max_contacts=1, the default: the request the query
caches),
the same method with ctypes alone (as with OPX_CTYPES_ONLY=1), and the bare
ctypes call of opx_query_collide with everything prepared (what no binding
built on ctypes alone can go below).

    python_overhead.py [--quick] [--calls N] [--rounds R] [--c-program PATH]
                       [--rust-program PATH] [--json FILE]

Run from anywhere after a build: the build tree's library and programs are
found through $OPX_BUILD_DIR (default: build/ in the repository); the Rust
program is built in release by `cmake --build build --target
opx-bench-call-overhead-rust` (cargo), and is left out with a message when
absent.  Prints the CPU and a table; exits 77 when numpy or the C program
is missing.
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
    parser.add_argument("--rust-program", default=os.path.join(
        BUILD, "bindings", "cargo-target", "release", "examples", "call_overhead"))
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
    """The Python callers on the scene, each a loop timing `calls` calls as
    a user's loop makes them (ns per call, thread CPU time)."""

    def __init__(self, octoprox):
        from octoprox import _library, query
        self.query_module = query
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

    def python_query_collide_keyword(self, calls):
        # A keyword (the default value) makes it the compiled cached-request call.
        collide, tree, links = self.query.collide, self.tree, self.links
        start = time.thread_time_ns()
        for _ in range(calls):
            collide(tree, links, max_contacts=1)
        return (time.thread_time_ns() - start) / calls

    def python_query_collide_ctypes(self, calls):
        # The Python method's ctypes path: what it runs without octoprox._fastcall.
        query_class = type(self.query)
        method = query_class.collide
        query_class.collide = getattr(method, "__wrapped__", method)
        try:
            return self.python_query_collide(calls)
        finally:
            query_class.collide = method

    def python_ctypes_call(self, calls):
        bare, result = self.bare, self.result
        query, tree, links = self.query._raw, self.tree._raw, self.links._raw
        start = time.thread_time_ns()
        for _ in range(calls):
            bare(query, tree, links, None, result)
        return (time.thread_time_ns() - start) / calls


def program_round(program, calls):
    """One round of the C or Rust program: its ns per call."""
    run = subprocess.run([program, "--calls", str(calls), "--rounds", "1"], capture_output=True,
                         text=True, check=True)
    return float(run.stdout.split()[-1])


def measure(args, octoprox):
    callers = PythonCallers(octoprox)
    programs = {"c": args.c_program}
    if args.rust_program:
        programs["rust_query_collide"] = args.rust_program
    names = ("python_ctypes_call", "python_query_collide", "python_query_collide_keyword",
             "python_query_collide_ctypes")
    rounds = {name: [] for name in tuple(programs) + names}
    for name in names:
        getattr(callers, name)(max(1, args.calls // 10))  # warm-up
    for _ in range(args.rounds):
        for name, program in programs.items():
            rounds[name].append(program_round(program, args.calls))
        for name in names:
            rounds[name].append(getattr(callers, name)(args.calls))
    return {name: statistics.median(values) for name, values in rounds.items()}


ROWS = [("C, `opx_query_collide`", "c"), ("Rust, `Query::collide`", "rust_query_collide"),
        ("Python, the bare ctypes call", "python_ctypes_call"),
        ("Python, `Query.collide`", "python_query_collide"),
        ("Python, `Query.collide` with a keyword", "python_query_collide_keyword"),
        ("Python, `Query.collide`, ctypes alone", "python_query_collide_ctypes")]


def report(figures, args, extension):
    c = figures["c"]
    print(f"CPU: {cpu_name()}")
    print(f"Python {platform.python_version()}; median of {args.rounds} rounds of "
          f"{args.calls} calls; load average {os.getloadavg()[0]:.2f}")
    print(f"octoprox._fastcall: {extension or 'not found (Query.collide uses ctypes alone)'}")
    print("| caller | us per call | over C |")
    print("| --- | --- | --- |")
    for label, key in ROWS:
        if key in figures:
            print(f"| {label} | {figures[key] / 1000:.2f} | {figures[key] / c:.2f}x |")


def main():
    args = parse()
    if not os.path.exists(args.c_program):
        print(f"python_overhead: skipped: {args.c_program} not found (build opx-bench-call-overhead)")
        return 77
    try:
        octoprox = import_octoprox()
    except ImportError as error:
        if getattr(error, "name", None) != "numpy":
            print(f"python_overhead: the octoprox package cannot be imported: {error}")
            return 1
        print(f"python_overhead: skipped: numpy is missing ({error})")
        return 77
    if not os.path.exists(args.rust_program):
        print(f"python_overhead: Rust left out: {args.rust_program} not found (build "
              "opx-bench-call-overhead-rust)")
        args.rust_program = None
    from octoprox import _calls
    extension = _calls.EXTENSION and _calls.EXTENSION.__file__
    figures = measure(args, octoprox)
    report(figures, args, extension)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(dict(figures, cpu=cpu_name(), python=platform.python_version(),
                           python_extension=bool(extension), calls=args.calls,
                           rounds=args.rounds, unit="ns per call"), f, indent=1)
            f.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
