"""octoprox.io: PCD and PLY files written here (ascii, binary, LZF
binary_compressed) and the shared RGB-D frame read as numpy arrays, and
bad files raising the library's errors with the Python function named."""
import math
import os
import pathlib
import struct
import tempfile
import unittest

import numpy as np

import octoprox
from octoprox import io

from scenes import REPO, skip_without_data

XYZ_RGB = "FIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n"
FRAME = "rgbd/frame_20121214T142255.814212"


def lzf_literals(data):
    """LZF data that only copies: runs of at most 32 bytes, each after a
    control byte of its length - 1 (valid input for any LZF decoder)."""
    out = bytearray()
    for start in range(0, len(data), 32):
        run = data[start:start + 32]
        out.append(len(run) - 1)
        out += run
    return bytes(out)


def compressed_pcd(header, points, extra=None, announced=None):
    """A binary_compressed PCD of float32 x y z (and uint32 `extra`), the
    fields one after another as PCL lays them out."""
    fields = np.ascontiguousarray(points, dtype=np.float32).T.tobytes()
    if extra is not None:
        fields += np.asarray(extra, dtype=np.uint32).tobytes()
    block = lzf_literals(fields)
    size = len(fields) if announced is None else announced
    return header.encode() + struct.pack("<II", len(block), size) + block


def data_dir():
    """The shared data folder: $OPX_DATA_DIR, else ../shared/data beside the repository."""
    return os.environ.get("OPX_DATA_DIR") or os.path.join(REPO, "..", "shared", "data")


class Files(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def write(self, name, content):
        path = os.path.join(self.dir.name, name)
        with open(path, "wb") as f:
            f.write(content.encode() if isinstance(content, str) else content)
        return path


class ReadPcd(Files):
    def test_an_organized_ascii_cloud_and_its_viewpoint(self):
        path = self.write("grid.pcd", XYZ_RGB + "WIDTH 3\nHEIGHT 2\nVIEWPOINT 1 2 3 0 1 0 0\n"
                          "POINTS 6\nDATA ascii\n" + "".join(
                              f"{i} {-i} {0.5 * i} 7\n" if i != 4 else "nan nan nan 0\n"
                              for i in range(6)))
        cloud = io.read_pcd(pathlib.Path(path))
        self.assertEqual(cloud.points.dtype, np.float32)
        self.assertEqual(cloud.points.shape, (6, 3))
        self.assertEqual((cloud.width, cloud.height, cloud.encoding), (3, 2, "ascii"))
        self.assertEqual(cloud.grid().shape, (2, 3, 3))
        np.testing.assert_array_equal(cloud.grid()[1, 2], [5, -5, 2.5])
        self.assertTrue(np.isnan(cloud.points[4]).all())
        # VIEWPOINT tx ty tz qw qx qy qz -> x y z qx qy qz qw
        self.assertTrue(cloud.has_viewpoint)
        self.assertEqual(cloud.viewpoint, (1.0, 2.0, 3.0, 1.0, 0.0, 0.0, 0.0))

    def test_a_binary_cloud_without_viewpoint(self):
        points = np.arange(12, dtype=np.float32).reshape(4, 3)
        body = b"".join(p.tobytes() + struct.pack("<I", 0) for p in points)
        path = self.write("binary.pcd", (XYZ_RGB + "WIDTH 4\nDATA binary\n").encode() + body)
        cloud = io.read_pcd(path)
        np.testing.assert_array_equal(cloud.points, points)
        self.assertEqual((cloud.width, cloud.height, cloud.encoding), (4, 1, "binary"))
        self.assertFalse(cloud.has_viewpoint)
        self.assertEqual(cloud.viewpoint, (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0))

    def test_a_compressed_cloud(self):
        points = np.random.default_rng(3).normal(size=(50, 3)).astype(np.float32)
        path = self.write("lzf.pcd", compressed_pcd(XYZ_RGB + "WIDTH 10\nHEIGHT 5\n"
                                                    "DATA binary_compressed\n", points, range(50)))
        cloud = io.read_pcd(path)
        self.assertEqual(cloud.encoding, "binary_compressed")
        np.testing.assert_array_equal(cloud.points, points)
        self.assertEqual(cloud.grid().shape, (5, 10, 3))

    def test_corrupt_compressed_clouds_raise(self):
        header = XYZ_RGB + "WIDTH 10\nDATA binary_compressed\n"
        points = np.ones((10, 3))
        lying = self.write("lying.pcd", compressed_pcd(header, points, range(10), announced=164))
        with self.assertRaisesRegex(octoprox.CorruptDataError, "read_pcd: .*lying.pcd.*164"):
            io.read_pcd(lying)
        cut = self.write("cut.pcd", compressed_pcd(header, points, range(10))[:-20])
        with self.assertRaisesRegex(ValueError, "truncated"):
            io.read_pcd(cut)

    def test_bad_files_raise_the_library_errors(self):
        with self.assertRaisesRegex(OSError, "read_pcd: .*missing.pcd"):
            io.read_pcd(os.path.join(self.dir.name, "missing.pcd"))
        integers = self.write("int.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE I I I\nCOUNT 1 1 1\n"
                              "WIDTH 1\nDATA ascii\n1 2 3\n")
        with self.assertRaises(octoprox.UnsupportedError):
            io.read_pcd(integers)
        ply = self.write("cloud.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n"
                         "property float y\nproperty float z\nend_header\n")
        with self.assertRaisesRegex(ValueError, "read_pcd: .* is not a PCD file"):
            io.read_pcd(ply)


class ReadPly(Files):
    def test_ascii_and_binary_vertices(self):
        header = ("ply\nformat {}\nelement vertex 3\nproperty double x\nproperty double y\n"
                  "property double z\nproperty uchar red\nelement face 0\n"
                  "property list uchar int vertex_indices\nend_header\n")
        expected = np.array([[0, 1, 2], [3.5, -4, 5], [6, 7, 1e-3]], dtype=np.float32)
        ascii_path = self.write("a.ply", header.format("ascii 1.0") + "".join(
            f"{x} {y} {z} 255\n" for x, y, z in expected.astype(np.float64)))
        binary_path = self.write("b.ply", header.format("binary_little_endian 1.0").encode() + b"".join(
            struct.pack("<dddB", *map(float, p), 255) for p in expected))
        for path in (ascii_path, binary_path):
            points = io.read_ply(path)
            self.assertEqual((points.dtype, points.shape), (np.float32, (3, 3)))
            np.testing.assert_array_equal(points, expected)

    def test_bad_files_raise(self):
        big_endian = self.write("be.ply", "ply\nformat binary_big_endian 1.0\nelement vertex 0\n"
                                "end_header\n")
        with self.assertRaisesRegex(octoprox.UnsupportedError, "read_ply: .*binary_big_endian"):
            io.read_ply(big_endian)
        with self.assertRaisesRegex(ValueError, "read_ply: .* is not a PLY file"):
            io.read_ply(self.write("x.pcd", XYZ_RGB + "WIDTH 1\nDATA ascii\n1 2 3 4\n"))


class SharedRgbdFrame(unittest.TestCase):
    """The shared RGB-D frame: its LZF original and its binary copy."""

    def setUp(self):
        self.original = os.path.join(data_dir(), FRAME + ".pcd")
        self.binary = os.path.join(data_dir(), FRAME + "_binary.pcd")
        if not (os.path.exists(self.original) and os.path.exists(self.binary)):
            skip_without_data(self, f"{self.original} not found: set OPX_DATA_DIR to the shared data folder")

    def test_the_compressed_original_equals_its_binary_copy(self):
        original, binary = io.read_pcd(self.original), io.read_pcd(self.binary)
        self.assertEqual(original.encoding, "binary_compressed")
        self.assertEqual((original.width, original.height), (640, 480))
        self.assertEqual(original.points.shape, (307200, 3))
        np.testing.assert_array_equal(original.points, binary.points)  # NaN where NaN
        self.assertEqual(int(np.isfinite(original.points).all(axis=1).sum()), 271575)
        # VIEWPOINT 0 0 0 0 1 0 0: a half turn about x (qx = 1, qw = 0).
        self.assertEqual(original.viewpoint, (0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0))
        finite = original.points[np.isfinite(original.points).all(axis=1)]
        self.assertTrue(math.isclose(finite[:, 2].min(), 0.671, abs_tol=6e-4))  # the data README


if __name__ == "__main__":
    unittest.main()
