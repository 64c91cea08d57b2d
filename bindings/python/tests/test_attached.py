"""Objects attached to links (LinkSet.attach_object, attach_box,
attach_sphere, attach_cylinder, World.attach_to) and world= on Query.path,
check_configurations, check_motion and check_motions: a box grasped
between two fingers collides with them unless they are touch links;
attached objects move with their link and meet the octree and world
objects, the answers naming them; batches with a world equal the single
calls for 1 to 3 threads; bad input raises naming the method."""
import math
import unittest

import numpy as np

import octoprox

from scenes import C0, one_cell_map
from test_batch import load_arm, random_rows, scatter_map

ALL = octoprox.ALL_CONTACTS


def gripper():
    """A palm at the origin and two fingers 4 cm apart along y, each a
    2 x 2 x 6 cm box whose inner face is 2 cm from the centre."""
    links = octoprox.LinkSet()
    for name in ("palm", "finger_l", "finger_r"):
        links.add_link(name)
    links.add_box(0, (0.1, 0.1, 0.02))
    links.add_box(1, (0.02, 0.02, 0.06))
    links.add_box(2, (0.02, 0.02, 0.06))
    links.set_poses([(0, 0, 0), (0, 0.03, 0.05), (0, -0.03, 0.05)])
    for a, b in (("palm", "finger_l"), ("palm", "finger_r"), ("finger_l", "finger_r")):
        links.set_pair_enabled(a, b, False)
    return links


def scatter_world(seed=5):
    rng = np.random.default_rng(seed)
    world = octoprox.World()
    for i in range(30):
        at = (rng.uniform(-0.8, 0.8), rng.uniform(-0.8, 0.8), rng.uniform(0.2, 1.4))
        world.add_sphere(f"ball {i}", rng.uniform(0.08, 0.2), pose=at)
    return world


class Attached(unittest.TestCase):
    def test_grasped_box_and_touch_links(self):
        links, query = gripper(), octoprox.Query()
        self.assertFalse(query.self_collide(links).collided)
        # 4.2 cm wide between faces 4 cm apart: 1 mm into each finger.
        index = links.attach_box("palm", "part", (0.02, 0.042, 0.03), pose=(0, 0, 0.05))
        self.assertEqual(index, 0)
        result = query.self_collide(links, max_contacts=ALL)
        self.assertEqual(result.contact_count, 2)
        rows = query.self_contacts()
        self.assertEqual(set(rows["link_b"]), {1, 2})
        self.assertEqual(list(rows["attached_a"]), [0, 0])
        self.assertEqual(list(rows["attached_b"]), [-1, -1])
        distance = query.self_distance(links, signed_distance=True)
        self.assertAlmostEqual(distance.distance, -0.001, places=9)
        self.assertEqual(distance.attached_a, 0)
        links.detach("part")
        self.assertEqual(links.attached_count, 0)
        links.attach_box("palm", "part", (0.02, 0.042, 0.03), pose=(0, 0, 0.05),
                         touch_links=["finger_l", "finger_r"])
        self.assertFalse(query.self_collide(links).collided)
        self.assertEqual(links.attached_touch_links("part"), [1, 2])
        self.assertEqual(links.attached_link("part"), 0)

    def test_attached_object_meets_the_map_and_the_world(self):
        links = octoprox.LinkSet()
        links.add_link("hand")
        links.add_sphere(0, 0.01, pose=(0.0, 0.0, 1.0))  # far above the tray
        links.attach_object(0, "tray", [dict(kind="box", size=(0.5, 0.5, 0.02)),
                                         dict(kind=octoprox.ShapeKind.SPHERE, radius=0.05,
                                              pose=(0.0, 0.0, 0.1))], pose=(0, 0, 0.5))
        self.assertEqual(links.attached_shape_count(0), 2)
        self.assertEqual(links.attached_shape("tray", 1).pose[:3], (0.0, 0.0, 0.1))
        self.assertEqual(links.attached_pose(0)[:3], (0.0, 0.0, 0.5))
        world = octoprox.World()
        world.add_sphere("ball", 0.05, pose=(0.0, 0.0, 0.56))  # resting on the tray
        query = octoprox.Query()
        hit = query.collide(None, links, world=world, max_contacts=ALL)
        self.assertTrue(hit.collided)
        rows = query.contacts()
        self.assertEqual(set(rows["attached"]), {0})
        self.assertEqual(set(rows["shape"]), {0, 1})
        links.set_poses([(0.0, 0.0, 1.0)])  # the tray moves with its link
        self.assertFalse(query.collide(None, links, world=world).collided)
        near = query.distance(None, links, world=world)
        self.assertEqual(near.attached, 0)
        self.assertAlmostEqual(near.distance, 1.49 - 0.61, places=9)  # tray bottom, ball top
        # The one-cell map [0, 0.25]^3: the tray 1 mm into its top face.
        links.set_poses([(C0, C0, 0.25 - 0.001 + 0.01 - 0.5)])
        hit = query.collide(one_cell_map(), links, max_contacts=ALL)
        self.assertTrue(hit.collided)
        self.assertIn(0, set(query.contacts()["attached"]))

    def test_world_object_attached_where_it_stands(self):
        links = octoprox.LinkSet()
        links.add_link("hand")
        links.add_sphere(0, 0.01)
        turned = (1.0, 0.0, 0.0, 0.0, 0.0, math.sin(0.5), math.cos(0.5))
        links.set_poses([turned])
        world = octoprox.World()
        world.add_cylinder("can", 0.04, 0.12, pose=(1.0, 0.5, 0.0))
        index = world.attach_to("can", links, "hand")
        self.assertEqual(links.attached_names, ["can"])
        x, y, z = links.attached_pose(index)[:3]
        self.assertAlmostEqual(x, 0.5 * math.sin(1.0))
        self.assertAlmostEqual(y, 0.5 * math.cos(1.0))
        query = octoprox.Query()
        self.assertTrue(query.collide(None, links, world=world).collided)  # the original
        world.set_enabled("can", False)
        self.assertFalse(query.collide(None, links, world=world).collided)

    def test_bad_input_raises_naming_the_method(self):
        links = gripper()
        with self.assertRaisesRegex(octoprox.InvalidArgumentError,
                                    r"LinkSet.attach_box.*touch_links\[0\] \"thumb\""):
            links.attach_box(0, "part", (0.1, 0.1, 0.1), touch_links=["thumb"])
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, r"LinkSet.attach_sphere.*link 7"):
            links.attach_sphere(7, "part", 0.1)
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, r"LinkSet.attach_box.*pose"):
            links.attach_box(0, "part", (0.1, 0.1, 0.1), pose=(math.nan, 0, 0))
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, r"attach_object.*shape_count"):
            links.attach_object(0, "part", [])
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, r"attach_object.*shapes\[1\]"):
            links.attach_object(0, "part", [dict(kind="sphere", radius=0.1),
                                            dict(kind="sphere", radius=-1.0)])
        with self.assertRaisesRegex(ValueError, "attach_object: kind"):
            links.attach_object(0, "part", [dict(radius=0.1)])
        with self.assertRaisesRegex(TypeError, "touch_links"):
            links.attach_box(0, "part", (0.1, 0.1, 0.1), touch_links="finger_l")
        self.assertEqual(links.attached_count, 0)
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "LinkSet.detach.*object 0"):
            links.detach(0)
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "LinkSet.find_attached"):
            links.find_attached("part")


class WithAWorld(unittest.TestCase):
    def test_batches_equal_single_calls_every_thread_count(self):
        arm, tree, world = load_arm(), scatter_map(), scatter_world()
        rows = random_rows(80)
        single = octoprox.Query()
        expected = []
        for q in rows:
            arm.set_joint_positions(q)
            expected.append(bool(single.collide(tree, arm, world=world, max_contacts=0).collided))
        self.assertTrue(0 < sum(expected) < len(expected))
        for threads in (1, 2, 3):
            collided = octoprox.Query().check_configurations(tree, arm, rows, threads=threads,
                                                             world=world)
            self.assertEqual(list(collided), expected, threads)
        alone, distances = octoprox.Query().check_configurations(None, arm, rows, world=world,
                                                                 distance=True, threads=2)
        arm.set_joint_positions(rows[3])
        self.assertEqual(distances[3], single.distance(None, arm, world=world).distance)
        plain = octoprox.Query().check_configurations(tree, arm, rows)
        self.assertTrue(np.any(np.array(expected) > plain))  # the world adds collisions

    def test_motions_and_paths(self):
        arm, tree, world = load_arm(), scatter_map(), scatter_world()
        starts = random_rows(12, seed=3)
        goals = starts + 0.3
        query = octoprox.Query()
        collided, fractions = query.check_motions(tree, arm, starts, goals, resolution=0.05,
                                                  threads=2, world=world)
        for m in range(len(starts)):
            one = query.check_motion(tree, arm, starts[m], goals[m], resolution=0.05, world=world)
            self.assertEqual(one.collided, collided[m])
            self.assertEqual(one.first_collision_fraction, fractions[m])
        poses = []
        for q in starts:
            arm.set_joint_positions(q)
            poses.append(arm.poses())
        path = query.path(None, arm, np.array(poses), world=world, compute_distance=True)
        first = -1
        for w, q in enumerate(starts):
            arm.set_joint_positions(q)
            if query.collide(None, arm, world=world).collided:
                first = w
                break
        self.assertEqual(path.first_colliding_waypoint, first)
        with self.assertRaisesRegex(octoprox.InvalidArgumentError, "Query.path.*compute_cost"):
            query.path(None, arm, np.array(poses), world=world, compute_cost=True)
        with self.assertRaisesRegex(TypeError, "Query.check_motions.*None with a world"):
            query.check_motions(None, arm, starts, goals)
        with self.assertRaisesRegex(TypeError, "Query.path.*World"):
            query.path(tree, arm, np.array(poses), world=tree)


if __name__ == "__main__":
    unittest.main()
