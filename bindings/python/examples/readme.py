import sys
import numpy as np
import octoprox

# The sensor frame: a PCD file given on the command line (its VIEWPOINT is
# the sensor pose), else two points seen by a sensor 1.2 m up.
if len(sys.argv) > 1:
    cloud = octoprox.io.read_pcd(sys.argv[1])
    frame, sensor = cloud.points, cloud.viewpoint
else:
    frame, sensor = np.array([[1.0, 0.0, 0.0], [1.0, 0.5, 0.0]], dtype=np.float32), (0.0, 0.0, 1.2)
with octoprox.Octree(resolution=0.05) as world, octoprox.LinkSet() as robot:
    world.insert_points(frame, sensor_pose=sensor)
    hand = robot.add_link("hand")
    robot.add_sphere(hand, radius=0.08)
    robot.set_poses([[0.95, 0.0, 1.2]])  # map frame, metres
    hit = octoprox.Query().collide(world, robot, unknown_policy=octoprox.UNKNOWN_OCCUPIED)
    print("collided:", bool(hit.collided))
