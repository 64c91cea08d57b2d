#!/usr/bin/env python3
"""ctest readme_examples: every code block of README.md preceded by a
`<!-- example: PATH -->` line must equal the file PATH (relative to the
repository), and those files must run and print "collided: true" (any
case: both examples check a hand placed in a sensor frame's obstacle).
Usage:
    check_readme.py REPO PYTHON [CARGO]
Python examples run with PYTHON; Rust examples (bindings/rust/octoprox/
examples/NAME.rs) with `CARGO run --offline --example NAME` when CARGO is
given.  The environment (OPX_LIBRARY, OPX_LIB_DIR, ...) comes from ctest.
"""
import os
import re
import subprocess
import sys

MARKER = re.compile(r"<!-- example: (\S+) -->\n```[a-z]*\n(.*?)```\n", re.S)


def main(repo, python, cargo=None):
    with open(os.path.join(repo, "README.md")) as f:
        blocks = MARKER.findall(f.read())
    if len({os.path.splitext(path)[1] for path, _ in blocks}) < 2:
        print("README.md: expected a Rust and a Python example marked <!-- example: PATH -->")
        return 1
    failures = 0
    for path, code in blocks:
        with open(os.path.join(repo, path)) as f:
            if f.read() != code:
                print(f"README.md: the block marked {path} differs from the file")
                failures += 1
                continue
        if path.endswith(".py"):
            command = [python, os.path.join(repo, path)]
        elif cargo:
            name = os.path.splitext(os.path.basename(path))[0]
            command = [cargo, "run", "--offline", "--quiet", "--example", name]
        else:
            print(f"{path}: not run (no cargo)")
            continue
        run = subprocess.run(command, cwd=os.path.join(repo, "bindings", "rust"),
                             capture_output=True, text=True)
        print(f"{path}: exit {run.returncode}: {run.stdout.strip()} {run.stderr.strip()}")
        if run.returncode != 0 or "collided: True" not in run.stdout.replace("true", "True"):
            failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
