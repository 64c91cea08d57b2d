#!/usr/bin/env python3
"""Loads an OctoMap, a robot's URDF, places the robot and checks it:
collision (unseen space counted as an obstacle or not) and the distance to
the closest obstacle, with the links involved.

    check_robot.py [--map MAP.bt] [--urdf ROBOT.urdf] [--package NAME=DIR]
                   [--at X Y Z] [--joint NAME=VALUE ...] [--unknown-occupied]

Without --map/--urdf it uses the shared data ($OPX_DATA_DIR, else
../shared/data beside the repository): the geb079 map and the PR2.
Exit status: 0 when the robot is collision-free, 1 when it collides,
77 when the default data is absent.
"""
import argparse
import os
import sys

import octoprox

HERE = os.path.dirname(os.path.abspath(__file__))
PR2_PACKAGE = "moveit_resources_pr2_description"


def data_dir():
    default = os.path.join(HERE, "..", "..", "..", "..", "shared", "data")
    return os.environ.get("OPX_DATA_DIR") or os.path.normpath(default)


def parse():
    data = data_dir()
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--map", default=os.path.join(data, "maps", "geb079.bt"))
    parser.add_argument("--urdf", default=os.path.join(data, "robots", "pr2_description",
                                                       "urdf", "robot.xml"))
    parser.add_argument("--package", action="append", default=[
        f"{PR2_PACKAGE}={os.path.join(data, 'robots', 'pr2_description')}"],
        help="NAME=DIR resolving package://NAME/ mesh names")
    parser.add_argument("--at", nargs=3, type=float, default=(0.0, 0.0, 0.0),
                        metavar=("X", "Y", "Z"), help="the robot's root link, map frame (m)")
    parser.add_argument("--joint", action="append", default=[], metavar="NAME=VALUE",
                        help="a joint position (rad or m)")
    parser.add_argument("--unknown-occupied", action="store_true",
                        help="count never-observed space as an obstacle")
    return parser.parse_args()


def main():
    args = parse()
    for path in (args.map, args.urdf):
        if not os.path.exists(path):
            print(f"check_robot: {path} not found (set OPX_DATA_DIR or pass --map/--urdf)")
            return 77
    joints = {name: float(value) for name, value in (j.split("=", 1) for j in args.joint)}
    with octoprox.Octree.load(args.map) as world, \
            octoprox.LinkSet.from_urdf(args.urdf, package_dirs=args.package) as robot, \
            octoprox.Query() as query:
        robot.set_named_joint_positions(joints, base_pose=args.at)
        policy = octoprox.UNKNOWN_OCCUPIED if args.unknown_occupied else octoprox.UNKNOWN_FREE
        hit = query.collide(world, robot, unknown_policy=policy, max_contacts=100)
        links = sorted({robot.link_name(i) for i in query.contacts()["link"]})
        shown = ", ".join(links[:4]) + (f" and {len(links) - 4} more" if len(links) > 4 else "")
        near = query.distance(world, robot, unknown_policy=policy)
        print(f"map {os.path.basename(args.map)}: {world.stats.leaves_occupied} occupied leaves "
              f"at {world.options.resolution} m; robot {robot.link_count} links, "
              f"{robot.joint_count} joints, root at {tuple(args.at)}")
        print(f"collided: {bool(hit.collided)} ({hit.contact_count} contacts"
              f"{', truncated' if hit.truncated else ''}{': ' + shown if links else ''})")
        print(f"distance: {near.distance:.3f} m, from link {robot.link_name(near.link)}")
        return 1 if hit.collided else 0


if __name__ == "__main__":
    sys.exit(main())
