"""The package covers the whole C ABI: every exported symbol is declared,
every struct has the library's size, and the versions agree."""
import ctypes
import os
import re
import subprocess
import sys
import unittest

import octoprox
from octoprox import _library, _structs

from scenes import REPO


class EveryExportedSymbolIsDeclared(unittest.TestCase):
    def test_symbols_match_the_committed_list(self):
        with open(os.path.join(REPO, "tests", "abi", "exported_symbols.txt")) as f:
            exported = {line.strip() for line in f if line.strip()}
        declared = set(_library.SIGNATURES)
        self.assertEqual(exported - declared, set(), "symbols the Python package misses")
        self.assertEqual(declared - exported, set(), "declared symbols not exported")

    def test_every_function_has_argtypes_and_restype(self):
        for name, (restype, argtypes) in _library.SIGNATURES.items():
            function = getattr(octoprox.lib, name)
            self.assertEqual(function.argtypes, argtypes, name)
            self.assertIs(function.restype, restype, name)


class StructsMatchTheLibrary(unittest.TestCase):
    def test_sizes_are_the_library_sizes(self):
        # opx_x_init(ptr, size) sets struct_size to min(size, its own size):
        # with a big buffer, struct_size is the library's sizeof.
        for struct, init in _structs.VERSIONED.items():
            buffer = ctypes.create_string_buffer(4096)
            getattr(octoprox.lib, init)(ctypes.cast(buffer, ctypes.POINTER(struct)), 4096)
            library_size = ctypes.c_uint32.from_buffer(buffer).value
            self.assertEqual(ctypes.sizeof(struct), library_size, struct.__name__)

    def test_defaults_land_in_the_right_fields(self):
        request = _library.init_struct(octoprox.CollisionRequest)
        self.assertEqual((request.max_contacts, request.max_cost_boxes), (1, 16))
        self.assertEqual(request.unknown_probability, 0.5)
        self.assertEqual(_library.init_struct(octoprox.OctreeOptions).clamp_max, 0.971)
        self.assertEqual(_library.init_struct(octoprox.QueryOptions).morton_bits, 10)
        self.assertEqual(_library.init_struct(octoprox.PathResult).min_distance_waypoint, -1)
        self.assertEqual(_library.init_struct(octoprox.InsertOptions).max_range, -1.0)


class ConstantsMatchTheHeaders(unittest.TestCase):
    def test_every_integer_define_has_the_header_value(self):
        from octoprox import _arrays, _errors, linkset
        folder = os.path.join(REPO, "include", "octoprox")
        defines = {}
        for header in os.listdir(folder):
            with open(os.path.join(folder, header)) as f:
                # Plain integers only (a comment may follow), not expressions.
                pattern = r"^#define OPX_(\w+) \(?(-?\d+)u?\)?[ \t]*(?:/\*.*)?$"
                for name, value in re.findall(pattern, f.read(), re.M):
                    defines[name] = int(value)
        checked = 0
        for name, value in defines.items():
            for module in (octoprox, _errors, _arrays, linkset):
                if hasattr(module, name):
                    self.assertEqual(getattr(module, name), value, name)
                    checked += 1
        self.assertGreater(checked, 30)  # cells, errors, shapes, formats, joints...


class Versions(unittest.TestCase):
    def test_header_version_matches_the_c_header(self):
        with open(os.path.join(REPO, "include", "octoprox", "common.h")) as f:
            text = f.read()
        header = tuple(int(re.search(r"#define OPX_VERSION_%s (\d+)" % part, text).group(1))
                       for part in ("MAJOR", "MINOR", "PATCH"))
        self.assertEqual(octoprox.HEADER_VERSION, header)

    def test_runtime_version(self):
        self.assertEqual(octoprox.version(), "%d.%d.%d" % octoprox.HEADER_VERSION)
        major, minor, patch = octoprox.HEADER_VERSION
        self.assertEqual(octoprox.version_number(), major * 10000 + minor * 100 + patch)
        self.assertEqual(octoprox.status_name(-6), "OPX_ERROR_IO")

    def test_a_library_is_compatible_within_its_soname(self):
        major, minor, _ = octoprox.HEADER_VERSION
        self.assertTrue(_library._compatible(major, minor))
        self.assertFalse(_library._compatible(major + 1, minor))
        # 0.x: a later minor is another ABI; from 1.0 on it only adds.
        self.assertEqual(_library._compatible(major, minor + 1), major != 0)

    def test_the_soname_file_is_beside_the_library(self):
        path = os.environ.get("OPX_LIBRARY")
        if not path:
            self.skipTest("OPX_LIBRARY is not set")
        major, minor, _ = octoprox.HEADER_VERSION
        expected = "liboctoprox.so.%d" % major + (".%d" % minor if major == 0 else "")
        self.assertEqual(_library._SONAME, expected)
        self.assertTrue(os.path.exists(os.path.join(os.path.dirname(path), expected)), expected)


class Loader(unittest.TestCase):
    def test_a_wrong_opx_library_is_an_import_error(self):
        env = dict(os.environ, OPX_LIBRARY="/nonexistent/liboctoprox.so")
        run = subprocess.run([sys.executable, "-c", "import octoprox"], env=env,
                             capture_output=True, text=True)
        self.assertNotEqual(run.returncode, 0)
        self.assertIn("ImportError", run.stderr)
        self.assertIn("/nonexistent/liboctoprox.so", run.stderr)


if __name__ == "__main__":
    unittest.main()
