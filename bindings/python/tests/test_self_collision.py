"""Self-collision: Query.self_collide and Query.self_distance, the pairs a
link set checks (LinkSet.set_pair_enabled, an SRDF's) and the
never-colliding-pairs helper; the scenarios of the C test
tests/c/test_self_collision.c."""
import math
import os
import tempfile
import unittest

import octoprox

# base (a box on the floor) --shoulder (revolute z)--> arm (a capsule lying
# on the base) --slide (prismatic x)--> hand (a sphere at the arm's end).
ARM = """<robot name="arm">
  <link name="base"><collision><origin xyz="0 0 0.1"/><geometry><box size="0.4 0.4 0.2"/></geometry></collision></link>
  <link name="arm"><collision><origin xyz="0.3 0 0" rpy="0 1.5707963267948966 0"/>
    <geometry><cylinder radius="0.05" length="0.6"/></geometry></collision></link>
  <link name="hand"><collision><origin xyz="0 0 0.3"/><geometry><sphere radius="0.05"/></geometry></collision></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.2"/><axis xyz="0 0 1"/><limit lower="-1.5" upper="1.5" velocity="1" effort="10"/></joint>
  <joint name="slide" type="prismatic"><parent link="arm"/><child link="hand"/>
    <origin xyz="0.6 0 0"/><axis xyz="1 0 0"/><limit lower="0" upper="0.2" velocity="2" effort="5"/></joint>
</robot>"""
SRDF = """<robot name="arm"><disable_collisions link1="base" link2="arm" reason="Adjacent"/></robot>"""
ALL = 0xFFFFFFFF


def two_cubes(gap):
    """Two links holding a 0.1 m cube each, gap metres apart along x."""
    links = octoprox.LinkSet()
    for name in ("left", "right"):
        links.add_box(links.add_link(name), (0.1, 0.1, 0.1))
    links.set_poses([[0.0, 0.0, 0.0], [0.1 + gap, 0.0, 0.0]])
    return links


class SelfCollision(unittest.TestCase):
    def test_links_one_centimetre_apart(self):
        links, query = two_cubes(0.01), octoprox.Query()
        self.assertFalse(query.self_collide(links).collided)
        d = query.self_distance(links)
        self.assertTrue(d.found)
        self.assertAlmostEqual(d.distance, 0.01, places=12)
        self.assertEqual((d.link_a, d.link_b), (0, 1))
        self.assertAlmostEqual(d.point_on_a[0], 0.05, places=12)
        self.assertAlmostEqual(d.point_on_b[0], 0.06, places=12)
        links.set_padding(0.005)  # each side: the gap closes, touching collides
        self.assertTrue(query.self_collide(links).collided)
        self.assertTrue(query.self_distance(links).collided)
        links.set_pair_enabled("left", "right", False)
        self.assertFalse(links.pair_enabled(1, 0))
        self.assertFalse(query.self_collide(links).collided)
        self.assertFalse(query.self_distance(links).found)
        self.assertTrue(math.isinf(query.self_distance(links).distance))

    def test_contacts_carry_both_links_and_the_depth(self):
        links, query = two_cubes(-0.02), octoprox.Query()
        result = query.self_collide(links, max_contacts=ALL, compute_penetration=True)
        self.assertEqual((result.collided, result.contact_count, result.truncated), (1, 1, 0))
        contact = query.self_contacts()[0]
        self.assertEqual((contact["link_a"], contact["shape_a"], contact["link_b"],
                          contact["shape_b"]), (0, 0, 1, 0))
        self.assertAlmostEqual(contact["depth"], 0.02, places=12)
        self.assertAlmostEqual(contact["normal"][0], 1.0, places=12)
        signed = query.self_distance(links, signed_distance=True)
        self.assertAlmostEqual(signed.distance, -0.02, places=12)
        self.assertEqual(len(query.self_contacts()), 1)  # a distance query keeps them

    def test_a_cutoff_below_the_gap(self):
        d = octoprox.Query().self_distance(two_cubes(0.01), cutoff=0.005)
        self.assertEqual((d.found, d.distance), (0, 0.005))

    def test_srdf_pairs_start_disabled(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "arm.srdf")
            with open(path, "w") as f:
                f.write(SRDF)
            robot = octoprox.LinkSet.from_urdf_string(ARM, srdf=path)
        self.assertFalse(robot.pair_enabled("base", "arm"))
        self.assertTrue(robot.pair_enabled("arm", "hand"))
        query = octoprox.Query()
        self.assertFalse(query.self_collide(robot).collided)
        robot.set_pair_enabled("base", "arm", True)  # the arm lies on the base
        self.assertTrue(query.self_collide(robot).collided)

    def test_sampling_disables_the_pairs_that_never_collide(self):
        robot = octoprox.LinkSet.from_urdf_string(ARM)
        result = robot.disable_never_colliding_pairs(samples=200, also_always_colliding=True)
        # The hand (z >= 0.45) never reaches the base (z <= 0.2) nor the arm
        # (z <= 0.25); the arm always lies on the base.
        self.assertEqual((result.now, result.never, result.always), (0, 2, 1))
        for pair in (("base", "hand"), ("arm", "hand"), ("base", "arm")):
            self.assertFalse(robot.pair_enabled(*pair), pair)
        robot = octoprox.LinkSet.from_urdf_string(ARM)
        result = robot.disable_never_colliding_pairs(samples=200)
        self.assertEqual((result.now, result.never, result.always), (0, 2, 0))
        self.assertTrue(robot.pair_enabled("base", "arm"))
        robot = octoprox.LinkSet.from_urdf_string(ARM)
        result = robot.disable_never_colliding_pairs(samples=200, also_colliding_now=True)
        self.assertEqual((result.now, result.never), (1, 2))  # the arm on the base, now
        self.assertFalse(octoprox.Query().self_collide(robot).collided)

    def test_bad_arguments_name_the_function_and_the_argument(self):
        links, query = two_cubes(0.01), octoprox.Query()
        with self.assertRaises(octoprox.InvalidArgumentError) as caught:
            links.set_pair_enabled(0, 5, False)
        self.assertIn("opx_linkset_set_pair_enabled: b: link 5", str(caught.exception))
        with self.assertRaises(octoprox.InvalidArgumentError) as caught:
            links.pair_enabled(1, 1)
        self.assertIn("a pair is of two different links", str(caught.exception))
        with self.assertRaises(octoprox.InvalidArgumentError) as caught:
            query.self_distance(links, cutoff=-1.0)
        self.assertIn("opx_query_self_distance: request->cutoff", str(caught.exception))
        with self.assertRaises(octoprox.UnsupportedError):
            links.disable_never_colliding_pairs(samples=10)
        with self.assertRaises(TypeError):
            query.self_collide(octoprox.Octree(resolution=0.1))
        with self.assertRaises(TypeError):
            query.self_collide(links, no_such_field=1)


if __name__ == "__main__":
    unittest.main()
