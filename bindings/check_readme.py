#!/usr/bin/env python3
"""ctest readme_examples: every code block of README.md and of the
getting-started pages (docs/getting-started-*.md) preceded by a
`<!-- example: PATH -->` line must equal the file PATH (relative to the
repository), and those files must run:
  - README.md's print "collided: true" (any case: both examples check a
    hand placed in a sensor frame's obstacle);
  - each getting-started page has at least one, they exit 0 and print a
    "batch:" line, or exit 77 without the shared data: the test then
    exits 77 too (skipped) when nothing failed, and fails with
    OPX_REQUIRE_DATA=1.
Usage:
    check_readme.py REPO PYTHON [CARGO]
Python examples run with PYTHON; Rust examples (bindings/rust/octoprox/
examples/NAME.rs) with `CARGO run --offline --example NAME` when CARGO is
given; C examples are compiled with $CC against the headers of REPO and the
library at $OPX_LIBRARY, then run.  The shared data is $OPX_DATA_DIR, else
$OPX_DEFAULT_DATA_DIR.  The environment (OPX_LIBRARY, OPX_LIB_DIR, ...)
comes from ctest.
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

MARKER = re.compile(r"<!-- example: (\S+) -->\n```[a-z]*\n(.*?)```\n", re.S)
SKIPPED = 77


def documents(repo):
    """(document, what its examples must print) pairs."""
    pages = sorted(glob.glob(os.path.join(repo, "docs", "getting-started-*.md")))
    return [("README.md", "collided: True")] + [(os.path.relpath(p, repo), "batch:") for p in pages]


def command_for(repo, path, python, cargo, work):
    """The command running the example at path, or None when it cannot run here."""
    if path.endswith(".py"):
        return [python, os.path.join(repo, path)]
    if path.endswith(".rs"):
        if not cargo:
            return None
        name = os.path.splitext(os.path.basename(path))[0]
        return [cargo, "run", "--offline", "--quiet", "--example", name]
    if path.endswith(".c"):
        library = os.environ["OPX_LIBRARY"]
        program = os.path.join(work, os.path.splitext(os.path.basename(path))[0])
        lib_dir = os.path.dirname(library)
        compile_c = [os.environ.get("CC", "cc"), "-std=c99", "-pedantic", "-Wall", "-Wextra", "-Werror",
                     os.path.join(repo, path), "-I", os.path.join(repo, "include"),
                     "-L", lib_dir, "-loctoprox", f"-Wl,-rpath,{lib_dir}", "-o", program]
        built = subprocess.run(compile_c, capture_output=True, text=True)
        if built.returncode != 0:
            print(f"{path}: does not compile:\n{built.stderr}")
            return ["false"]
        return [program]
    raise ValueError(f"{path}: no runner for this kind of file")


def check_document(repo, document, expected, python, cargo, work, skipped):
    with open(os.path.join(repo, document)) as f:
        blocks = MARKER.findall(f.read())
    if document == "README.md" and len({os.path.splitext(p)[1] for p, _ in blocks}) < 2:
        print("README.md: expected a Rust and a Python example marked <!-- example: PATH -->")
        return 1
    if not blocks:
        print(f"{document}: no example marked <!-- example: PATH -->")
        return 1
    failures = 0
    for path, code in blocks:
        with open(os.path.join(repo, path)) as f:
            if f.read() != code:
                print(f"{document}: the block marked {path} differs from the file")
                failures += 1
                continue
        command = command_for(repo, path, python, cargo, work)
        if command is None:
            print(f"{path}: not run (no cargo)")
            continue
        run = subprocess.run(command, cwd=os.path.join(repo, "bindings", "rust"),
                             capture_output=True, text=True)
        print(f"{document}: {path}: exit {run.returncode}: {run.stdout.strip()} {run.stderr.strip()}")
        if run.returncode == SKIPPED and expected != "collided: True":
            if os.environ.get("OPX_REQUIRE_DATA") == "1":
                print(f"{path}: skipped without the shared data, and OPX_REQUIRE_DATA=1")
                failures += 1
            skipped.append(path)
            continue
        if run.returncode != 0 or expected not in run.stdout.replace("true", "True"):
            failures += 1
    return failures


def main(repo, python, cargo=None):
    repo = os.path.abspath(repo)
    if "OPX_DATA_DIR" not in os.environ and "OPX_DEFAULT_DATA_DIR" in os.environ:
        os.environ["OPX_DATA_DIR"] = os.environ["OPX_DEFAULT_DATA_DIR"]
    skipped = []
    with tempfile.TemporaryDirectory() as work:
        failures = sum(check_document(repo, document, expected, python, cargo, work, skipped)
                       for document, expected in documents(repo))
    if failures:
        return 1
    if skipped:
        print(f"skipped without the shared data: {', '.join(skipped)}")
        return SKIPPED
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
