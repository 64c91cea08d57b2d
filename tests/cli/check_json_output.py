#!/usr/bin/env python3
"""cli_json_output: with --json every run of `octoprox` prints exactly one
valid JSON object on stdout: the report when the command succeeds (exit 0,
or 1 for a collision), else one error object with the exit code's status
and the first message, whichever command fails and wherever it fails (the
command line, a missing or malformed file, a CSV path halfway through the
report, a map that cannot be written).

usage: check_json_output.py OCTOPROX"""
import json
import os
import subprocess
import sys
import tempfile

URDF = """<?xml version="1.0"?>
<robot name="slider">
  <link name="base"><collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
  <link name="tool"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>
  <joint name="slide" type="prismatic"><parent link="base"/><child link="tool"/>
    <origin xyz="0 0 0.5"/><axis xyz="1 0 0"/><limit lower="0" upper="3" effort="1" velocity="1"/></joint>
</robot>
"""
STATUS = {2: "usage_error", 3: "input_error", 4: "internal_error"}


def wall_cloud():
    """A wall of points at x = 2.05 (the C tests' scene)."""
    points = [(2.05, -1.0 + 0.1 * i, -0.5 + 0.1 * j) for i in range(21) for j in range(21)]
    header = ("VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
              f"WIDTH {len(points)}\nHEIGHT 1\nPOINTS {len(points)}\nDATA ascii\n")
    return header + "".join("%.3f %.3f %.3f\n" % p for p in points)


class Runner:
    def __init__(self, tool, folder):
        self.tool, self.folder, self.failures, self.runs = tool, folder, [], 0

    def path(self, name, content=None):
        path = os.path.join(self.folder, name)
        if content is not None:
            with open(path, "wb") as f:
                f.write(content.encode() if isinstance(content, str) else content)
        return path

    def run(self, *args):
        """Runs the tool with --json; the parsed stdout and the exit code."""
        self.runs += 1
        done = subprocess.run([self.tool, *args, "--json"], capture_output=True, text=True)
        try:
            return json.loads(done.stdout), done.returncode, done
        except json.JSONDecodeError as error:
            self.failures.append(f"{args}: stdout is not JSON ({error}): {done.stdout!r}")
            return None, done.returncode, done

    def expect_report(self, codes, *args):
        report, code, done = self.run(*args)
        if code not in codes or report is None or "error" in report:
            self.failures.append(f"{args}: exit {code}, expected {codes}; {done.stdout!r} {done.stderr!r}")
        return report

    def expect_error(self, code, message, *args):
        report, actual, done = self.run(*args)
        if report is None:
            return
        error = report.get("error") if isinstance(report, dict) else None
        if actual != code or not isinstance(error, dict) or len(report) != 1:
            self.failures.append(f"{args}: exit {actual} (expected {code}), {report}")
            return
        if error.get("exit_code") != code or error.get("status") != STATUS[code]:
            self.failures.append(f"{args}: error object {error} does not say exit {code}")
        if message not in error.get("message", "") or message not in done.stderr:
            self.failures.append(f"{args}: message {error.get('message')!r} lacks {message!r}")


def main():
    tool = sys.argv[1]
    with tempfile.TemporaryDirectory() as folder:
        r = Runner(tool, folder)
        cloud, urdf = r.path("wall.pcd", wall_cloud()), r.path("slider.urdf", URDF)
        map_path = r.path("wall.bt")
        # Reports that succeed are whole objects.
        r.expect_report({0}, "ingest", cloud, "--res", "0.1", "-o", map_path)
        r.expect_report({0}, "info", map_path)
        filtered = r.expect_report({0}, "ingest", cloud, "-o", r.path("filtered.bt"), "--urdf", urdf,
                                   "--joints", "slide=2", "--robot-padding", "0.05",
                                   "--clear-robot-volume")
        if filtered is not None and not all(
                isinstance(filtered["clouds"][0].get(name), int)
                for name in ("points_on_robot", "points_shadowed", "cells_cleared")):
            r.failures.append(f"ingest --urdf: no self-filtering counts in {filtered}")
        r.expect_report({0}, "check", map_path, "--urdf", urdf, "--distance", "--cost")
        r.expect_report({1}, "check", map_path, "--urdf", urdf, "--joints", "slide=2")
        r.expect_report({0, 1}, "check", map_path, "--urdf", urdf,
                        "--path", r.path("good.csv", "slide\n0\n2\n"))
        # A CSV separated by blanks fails after the report's head is written.
        r.expect_error(3, "space.csv", "check", map_path, "--urdf", urdf,
                       "--path", r.path("space.csv", "slide other\n0 1\n"))
        r.expect_error(3, "waypoint", "check", map_path, "--urdf", urdf,
                       "--path", r.path("unknown.csv", "nope\n0\n"))
        r.expect_error(2, "unknown option '--bogus'", "check", map_path, "--bogus")
        r.expect_error(2, "no map file given", "check")
        r.expect_error(2, "nope", "check", map_path, "--urdf", urdf, "--joints", "nope=1")
        r.expect_error(3, "missing.bt", "check", r.path("missing.bt"), "--urdf", urdf)
        r.expect_error(3, "bad.urdf", "check", map_path, "--urdf", r.path("bad.urdf", "<robot"))
        r.expect_error(3, "garbage.bt", "info", r.path("garbage.bt", "not a map\n"))
        r.expect_error(2, "--robot-padding needs --urdf", "ingest", cloud, "-o", r.path("x.bt"),
                       "--robot-padding", "0.1")
        r.expect_error(3, "missing.urdf", "ingest", cloud, "-o", r.path("x.bt"),
                       "--urdf", r.path("missing.urdf"))
        r.expect_error(3, "cut.pcd", "ingest", r.path("cut.pcd", wall_cloud()[:-400]),
                       "-o", r.path("cut.bt"))
        r.expect_error(3, "binary_compressed", "ingest",
                       r.path("lzf.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                                         "WIDTH 9\nDATA binary_compressed\n\x01\x00"),
                       "-o", r.path("lzf.bt"))
        r.expect_error(3, "/nonexistent-dir/m.bt", "ingest", cloud, "-o", "/nonexistent-dir/m.bt")
        r.expect_error(3, "/nonexistent-dir/m.obj", "export", map_path, "--obj", "/nonexistent-dir/m.obj")
        r.expect_error(2, "unknown command 'bogus'", "bogus")
    for failure in r.failures:
        print("FAIL:", failure)
    print(f"{r.runs - len(r.failures)} passed, {len(r.failures)} failed")
    return 1 if r.failures else 0


if __name__ == "__main__":
    sys.exit(main())
