"""World objects: octoprox.World built by hand (add_box, add_cylinder,
add_sphere, add_mesh, add_object/add_shape) and from MoveIt scene files,
its bookkeeping (len, names, poses, enabled flags, removal), and
Query.collide and Query.distance with world= (no octree, and beside the
one-cell map); the scenarios of the C tests tests/c/test_world*.c."""
import math
import os
import unittest

import numpy as np

import octoprox

from scenes import C0, REPO, RES, one_cell_map, sphere_at

SCENES = os.path.join(REPO, "tests", "data", "scenes")
ALL = octoprox.ALL_CONTACTS
TETRA = np.array([[0, 0, 0], [0.2, 0, 0], [0, 0.2, 0], [0, 0, 0.2]], dtype=np.float64)
FACES = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])


def kitchen():
    """A box, a cylinder standing on z, a sphere and a tetrahedron surface."""
    world = octoprox.World()
    world.add_box("crate", (0.2, 0.2, 0.2), pose=(2.0, 0.0, 0.0))
    world.add_cylinder("post", 0.05, 1.0, pose=(0.0, 2.0, 0.5))
    world.add_sphere("ball", 0.1, pose=(0.0, -2.0, 0.0))
    world.add_mesh("wedge", TETRA, FACES, pose=(-2.0, 0.0, 0.0))
    return world


class Building(unittest.TestCase):
    def test_objects_by_index_and_name(self):
        world = kitchen()
        self.assertEqual(len(world), 4)
        self.assertEqual(world.names, ["crate", "post", "ball", "wedge"])
        self.assertEqual(world.find("ball"), 2)
        self.assertEqual(world.pose("post")[:3], (0.0, 2.0, 0.5))
        shape = world.shape("post", 0)
        self.assertEqual(shape.kind, octoprox.ShapeKind.CYLINDER)
        self.assertAlmostEqual(shape.length, 1.0)
        self.assertEqual(world.shape("wedge", 0).triangles.shape, (4, 3))
        world.remove("post")  # later objects move down by one
        self.assertEqual(world.names, ["crate", "ball", "wedge"])
        self.assertEqual(world.find("wedge"), 2)
        world.set_enabled(0, False)
        self.assertFalse(world.enabled("crate"))
        self.assertTrue(world.enabled(1))

    def test_objects_of_several_shapes(self):
        world = octoprox.World()
        table = world.add_object("table", (1.0, 0.0, 0.0, 0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5)))
        self.assertEqual(world.add_shape(table, "box", (0, 0, 0.725), size=(1.2, 0.8, 0.05)), 0)
        self.assertEqual(world.add_shape("table", octoprox.ShapeKind.CAPSULE, radius=0.03,
                                         length=0.6), 1)
        self.assertEqual(world.add_shape(table, "convex", vertices=TETRA), 2)
        self.assertEqual(world.shape_count("table"), 3)

    def test_bad_input_raises_naming_the_method(self):
        world = kitchen()
        with self.assertRaisesRegex(ValueError, r"World.add_sphere: .*radius"):
            world.add_sphere("bad", -1.0)
        self.assertEqual(len(world), 4)  # no object left without its shape
        with self.assertRaisesRegex(ValueError, r"World.set_pose: .*pose.position\[0\]"):
            world.set_pose(0, (math.nan, 0, 0))
        with self.assertRaisesRegex(ValueError, r"World.remove: .*object 9"):
            world.remove(9)
        with self.assertRaisesRegex(ValueError, r"World.find: .*'chair'"):
            world.find("chair")
        world.close()
        with self.assertRaisesRegex(ValueError, "the world is closed"):
            len(world.names)


class SceneFiles(unittest.TestCase):
    def test_yaml_and_scene_text_give_the_same_world(self):
        yaml = octoprox.World.from_scene_file(os.path.join(SCENES, "kitchen.yaml"))
        text = octoprox.World.from_scene_file(os.path.join(SCENES, "kitchen.scene"))
        self.assertEqual(yaml.names, ["table", "ball", "wedge"])
        self.assertEqual(text.names, yaml.names)
        for name in yaml.names:
            np.testing.assert_allclose(yaml.pose(name), text.pose(name), atol=1e-12)
            self.assertEqual(yaml.shape_count(name), text.shape_count(name))

    def test_robowflex_scenes_give_the_same_world(self):
        # Poses as lists, types and operations as words, fixed frames.
        yaml = octoprox.World.from_scene_file(os.path.join(SCENES, "kitchen.yaml"))
        benchmark = octoprox.World.from_scene_file(os.path.join(SCENES, "kitchen_robowflex.yaml"))
        self.assertEqual(benchmark.names, yaml.names)
        for name in yaml.names:
            np.testing.assert_allclose(benchmark.pose(name), yaml.pose(name), atol=1e-12)
            self.assertEqual(benchmark.shape_count(name), yaml.shape_count(name))
        with self.assertRaisesRegex(octoprox.CorruptDataError,
                                    r"box_position_too_short.yaml: line 10: "
                                    r"world.collision_objects\[0\].primitive_poses\[0\].position: 2 values"):
            octoprox.World.from_scene_file(os.path.join(SCENES, "box_position_too_short.yaml"))

    def test_bad_scenes_name_the_line_and_the_field(self):
        bad = "world:\n  collision_objects:\n    - id: post\n      primitives:\n" \
              "        - type: 3\n          dimensions: [0.7]\n"
        with self.assertRaisesRegex(octoprox.CorruptDataError,
                                    r"line 6: world.collision_objects\[0\].primitives\[0\].dimensions"):
            octoprox.World.from_scene_string(bad)
        cone = bad.replace("type: 3", "type: 4")
        with self.assertRaisesRegex(octoprox.UnsupportedError, "CONE"):
            octoprox.World.from_scene_string(cone)
        with self.assertRaisesRegex(octoprox.CorruptDataError, r"line 6: object 'post' shape 0"):
            octoprox.World.from_scene_string("s\n* post\n0 0 0\n0 0 0 1\n1\ntorus\n", "scene")
        with self.assertRaisesRegex(ValueError, "format 'urdf'"):
            octoprox.World.from_scene_string("", "urdf")
        with self.assertRaises(octoprox.IoError):
            octoprox.World.from_scene_file(os.path.join(SCENES, "missing.yaml"))


class Queries(unittest.TestCase):
    def test_objects_alone(self):
        world, query = kitchen(), octoprox.Query()
        links = sphere_at(0.05, 2.14, 0.0, 0.0)  # 0.01 into the crate
        result = query.collide(None, links, world=world, max_contacts=ALL, compute_penetration=True)
        self.assertTrue(result.collided)
        contact = query.contacts()[0]
        self.assertEqual((contact["object"], contact["object_shape"]), (0, 0))
        self.assertAlmostEqual(contact["depth"], 0.01, places=9)
        self.assertEqual(contact["cell_size"], 0.0)
        links.set_poses([[0.0, 1.8, 0.5]])  # 0.15 - 0.05 from the post
        distance = query.distance(None, links, world=world, per_link=True)
        self.assertEqual(distance.object, 1)
        self.assertAlmostEqual(distance.distance, 0.1, places=12)
        np.testing.assert_allclose(distance.point_on_cell, (0.0, 1.95, 0.5), atol=1e-9)
        np.testing.assert_allclose(query.link_distances(), [0.1], atol=1e-12)
        world.set_enabled("post", False)
        self.assertNotEqual(query.distance(None, links, world=world).object, 1)

    def test_beside_the_map(self):
        tree, query = one_cell_map(), octoprox.Query()
        world = octoprox.World()
        world.add_box("crate", (0.2, 0.2, 0.2), pose=(0.6, C0, C0))
        links = sphere_at(0.13, 0.375, C0, C0)  # into the cell and the crate
        result = query.collide(tree, links, world=world, max_contacts=ALL)
        self.assertEqual(result.contact_count, 2)
        self.assertEqual(list(query.contacts()["object"]), [-1, 0])
        self.assertEqual(query.contacts()["cell_size"][0], RES)
        self.assertEqual(query.collide(tree, links, max_contacts=ALL).contact_count, 1)
        near = sphere_at(0.05, 0.42, C0, C0)  # 0.12 from the cell, 0.03 from the crate
        self.assertAlmostEqual(query.distance(tree, near, world=world).distance, 0.03, places=12)
        self.assertEqual(query.distance(tree, near).object, -1)

    def test_both_engines_agree(self):
        tree, world = one_cell_map(), kitchen()
        links = sphere_at(0.05, 0.4, C0, C0)
        for engine in ("direct", "amortized"):
            query = octoprox.Query(engine)
            self.assertAlmostEqual(query.distance(tree, links, world=world).distance,
                                   0.4 - RES - 0.05, places=12)

    def test_operands_are_checked(self):
        query, links = octoprox.Query(), sphere_at(0.1, 0, 0, 0)
        with self.assertRaisesRegex(ValueError, "Query.collide: .*tree is NULL"):
            query.collide(None, links)
        with self.assertRaisesRegex(TypeError, "Query.distance: expected"):
            query.distance(None, links, world="kitchen")
        with self.assertRaisesRegex(ValueError, "Query.collide: .*compute_cost"):
            query.collide(None, links, world=kitchen(), compute_cost=True)
        world = kitchen()
        world.close()
        with self.assertRaisesRegex(ValueError, "the world is closed"):
            query.collide(None, links, world=world)

    def test_the_query_keeps_no_world(self):
        query, links = octoprox.Query(), sphere_at(0.05, 2.14, 0.0, 0.0)
        self.assertTrue(query.collide(None, links, world=kitchen()).collided)
        # The world was freed; the query holds none, so a path query runs.
        result = query.path(one_cell_map(), links, [[[2.14, 0.0, 0.0]]])
        self.assertFalse(result.collided)


if __name__ == "__main__":
    unittest.main()
