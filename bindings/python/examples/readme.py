import numpy as np
import octoprox

with octoprox.Octree(resolution=0.05) as world, octoprox.LinkSet() as robot:
    frame = np.array([[1.0, 0.0, 0.0], [1.0, 0.5, 0.0]], dtype=np.float32)  # sensor frame
    world.insert_points(frame, sensor_pose=(0.0, 0.0, 1.2))  # the sensor is 1.2 m up
    hand = robot.add_link("hand")
    robot.add_sphere(hand, radius=0.08)
    robot.set_poses([[0.95, 0.0, 1.2]])  # map frame, metres
    hit = octoprox.Query().collide(world, robot, unknown_policy=octoprox.UNKNOWN_OCCUPIED)
    print("collided:", bool(hit.collided))
