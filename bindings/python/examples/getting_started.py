"""Getting started in Python: a map from a file, a robot from URDF, one
query, then a batch of configurations.  Uses the shared data
($OPX_DATA_DIR, else ../shared/data): the geb079 map and the PR2; exits 77
without it."""
import os
import sys

import numpy as np
import octoprox

data = os.environ.get("OPX_DATA_DIR", "../shared/data")
map_path = os.path.join(data, "maps", "geb079.bt")
urdf_path = os.path.join(data, "robots", "pr2_description", "urdf", "robot.xml")
package = "moveit_resources_pr2_description=" + os.path.join(data, "robots", "pr2_description")
if not os.path.exists(map_path):
    print(f"skipped: no {map_path} (set OPX_DATA_DIR)")
    sys.exit(77)

# A map from a .bt file (the resolution comes from the file) and a robot
# from URDF (package:// meshes resolved through NAME=DIR).
with octoprox.Octree.load(map_path) as world, \
        octoprox.LinkSet.from_urdf(urdf_path, package_dirs=[package]) as robot, \
        octoprox.Query() as query:
    # One query: every joint at 0, the root at the map origin.
    hit = query.collide(world, robot)
    near = query.distance(world, robot)
    print(f"collided: {bool(hit.collided)}, distance {near.distance:.3f} m")

    # A batch: 100 rows of every joint (model order), the right shoulder
    # swept from -2 to 0.5 rad, two threads, with distances.
    q = np.zeros((100, robot.joint_count))
    q[:, robot.find_joint("r_shoulder_pan_joint")] = np.linspace(-2.0, 0.5, 100)
    collided, distances = query.check_configurations(world, robot, q, threads=2, distance=True)
    print(f"batch: {collided.sum()} of {len(q)} configurations collide, "
          f"least distance {distances.min():.3f} m")
