"""Scenes shared by the tests, the same as the C tests' (tests/c/opx_test.h):
25 cm cells, the sensor at the centre C0 of the cell [0, RES)^3."""
import os

import octoprox

RES = 0.25
C0 = 0.125
REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))


def skip_without_data(case, message):
    """Skips the running test for absent shared data, or fails it when
    OPX_REQUIRE_DATA=1 (CI sets it)."""
    if os.environ.get("OPX_REQUIRE_DATA") == "1":
        case.fail(f"{message} and OPX_REQUIRE_DATA=1: the shared data is required")
    case.skipTest(message)


def one_cell_map():
    """One occupied cell [0, RES]^3 (p = 0.7); the rest unknown."""
    tree = octoprox.Octree(resolution=RES)
    tree.insert_points([[C0, C0, C0]], mode=octoprox.INSERT_ENDPOINTS)
    assert tree.stats.leaves_occupied == 1
    return tree


def sphere_at(radius, x, y, z):
    """One link "ball": a sphere of radius at (x, y, z), map frame."""
    links = octoprox.LinkSet()
    links.add_sphere(links.add_link("ball"), radius)
    links.set_poses([[x, y, z]])
    return links
