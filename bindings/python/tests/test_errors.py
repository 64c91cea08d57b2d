"""Status codes become exceptions carrying status and message, subclasses
of the builtin exceptions that fit; handles close deterministically."""
import gc
import unittest

import numpy as np

import octoprox
from octoprox import _errors

from scenes import C0, one_cell_map, sphere_at


class ErrorMapping(unittest.TestCase):
    def test_invalid_arguments_are_value_errors_naming_function_and_argument(self):
        with self.assertRaises(ValueError) as caught:
            octoprox.Octree(resolution=float("nan"))
        error = caught.exception
        self.assertIsInstance(error, octoprox.InvalidArgumentError)
        self.assertEqual(error.status, _errors.ERROR_INVALID_ARGUMENT)
        self.assertTrue(error.message.startswith("opx_octree_create"), error.message)
        self.assertIn("resolution", error.message)

    def test_io_errors_are_os_errors(self):
        with self.assertRaises(OSError) as caught:
            octoprox.Octree.load("/nonexistent/map.bt")
        self.assertIsInstance(caught.exception, octoprox.IoError)
        self.assertEqual(caught.exception.status, _errors.ERROR_IO)
        self.assertIn("/nonexistent/map.bt", str(caught.exception))

    def test_corrupt_data_is_a_value_error(self):
        with self.assertRaises(octoprox.CorruptDataError) as caught:
            octoprox.Octree.from_bytes(b"# Octomap OcTree binary file\nnonsense")
        self.assertIsInstance(caught.exception, ValueError)
        self.assertEqual(caught.exception.status, _errors.ERROR_CORRUPT)

    def test_an_uninitialised_struct_is_a_version_error(self):
        request = octoprox.CollisionRequest()  # struct_size 0
        with self.assertRaises(octoprox.VersionError) as caught:
            octoprox.lib.opx_query_collide(octoprox.Query(), one_cell_map(),
                                           sphere_at(0.1, 0, 0, 0), request,
                                           octoprox.CollisionResult())
        self.assertEqual(caught.exception.status, _errors.ERROR_VERSION)

    def test_every_status_has_its_class(self):
        expected = {-1: ValueError, -2: MemoryError, -5: NotImplementedError, -6: OSError,
                    -7: ValueError, -8: RuntimeError}
        for status, base in expected.items():
            error = _errors.error_for(status, "opx_x: message")
            self.assertIsInstance(error, base)
            self.assertIsInstance(error, octoprox.OctoproxError)
            self.assertEqual((error.status, error.message, str(error)),
                             (status, "opx_x: message", "opx_x: message"))
        self.assertIsNone(_errors.error_for(-6, "m").errno)
        self.assertEqual(type(_errors.error_for(-99, "m")), octoprox.OctoproxError)

    def test_bad_calls_leave_objects_usable(self):
        robot = octoprox.LinkSet()
        ball = robot.add_link("ball")
        with self.assertRaises(ValueError):
            robot.add_sphere(ball, -1.0)
        with self.assertRaises(ValueError):
            robot.add_sphere(7, 0.1)
        robot.add_sphere(ball, 0.1)
        with self.assertRaises(ValueError) as caught:
            robot.set_poses([[0, 0, 0, 0, 0, 0, 0]])  # a zero quaternion
        self.assertTrue(caught.exception.message.startswith("opx_linkset_set_poses"))
        with self.assertRaises(ValueError):
            robot.set_poses([[0, 0, 0], [1, 1, 1]])  # one link only
        with self.assertRaises(ValueError):
            robot.find_link("nothing")
        with self.assertRaises(ValueError):
            octoprox.Query().path(one_cell_map(), robot, np.zeros((2, 3, 7)))
        with self.assertRaises(ValueError):
            octoprox.Octree().insert_points(np.zeros((4, 2)))
        with self.assertRaises(TypeError):
            octoprox.Query().collide(one_cell_map(), robot, max_contact=3)  # a typo
        with self.assertRaises(TypeError):
            octoprox.Query().distance(robot, one_cell_map())  # swapped handles
        with self.assertRaises(ValueError):
            octoprox.Query(engine=42)
        robot.set_poses([[0.35, C0, C0]])
        self.assertEqual(octoprox.Query().collide(one_cell_map(), robot).collided, 1)


class Handles(unittest.TestCase):
    def test_context_managers_close_and_closed_handles_raise(self):
        with octoprox.Octree() as tree:
            self.assertFalse(tree.closed)
        self.assertTrue(tree.closed)
        with self.assertRaises(ValueError):
            tree.stats
        tree.close()  # closing twice is harmless

    def test_collected_handles_are_destroyed(self):
        robot = octoprox.LinkSet()
        finalizer = robot._finalizer
        del robot
        gc.collect()
        self.assertFalse(finalizer.alive)


if __name__ == "__main__":
    unittest.main()
