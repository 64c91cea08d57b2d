"""The PEP 517 build backend of the octoprox package, standard library only.

pip needs nothing from an index to build the package (no setuptools, no
wheel), and the build writes nothing into the source tree: the wheel, the
sdist and the metadata go only to the directories pip hands over.

The wheel carries liboctoprox when ``$OPX_LIBRARY`` (or the config setting
``library``: ``pip wheel -C library=PATH``) names the library to bundle by its
absolute path, e.g. ``$PWD/build/src/liboctoprox.so``: it is copied into the package under its SONAME
(liboctoprox.so.0.MINOR on 0.x, liboctoprox.so.MAJOR from 1.0 on), where the
package's loader looks first after ``$OPX_LIBRARY``, and the wheel is tagged
for this platform.  Without it the package uses the system's liboctoprox.

The wheel also carries octoprox._fastcall, the compiled call path of the
package's small queries, built for the interpreter running pip
(octoprox_extension.py: it needs Python.h and a C compiler, and
``--config-settings extension=no`` leaves it out); the wheel is then tagged
for that interpreter and platform (e.g. cp311-cp311-linux_x86_64).  Without
it the package calls the library through ctypes alone.
"""
import base64
import ctypes
import hashlib
import io
import os
import sys
import sysconfig
import tarfile
import tempfile
import time
import zipfile

import octoprox_extension as extension

try:
    import tomllib
except ImportError:  # Python < 3.11: pyproject.toml asks for tomli there
    import tomli as tomllib

_ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
_PACKAGE = "octoprox"
_SDIST_FILES = ("pyproject.toml", "README.md", "backend/octoprox_wheel.py",
                "backend/octoprox_extension.py")


def _project():
    with open(os.path.join(_ROOT, "pyproject.toml"), "rb") as f:
        return tomllib.load(f)["project"]


def _soname(version):
    major, minor = (int(part) for part in version.split(".")[:2])
    return "liboctoprox.so.%d.%d" % (major, minor) if major == 0 else "liboctoprox.so.%d" % major


def _metadata(project):
    lines = ["Metadata-Version: 2.1", "Name: " + project["name"], "Version: " + project["version"],
             "Summary: " + project["description"], "Requires-Python: " + project["requires-python"]]
    lines += ["Requires-Dist: " + dependency for dependency in project.get("dependencies", [])]
    lines.append("Description-Content-Type: text/markdown")
    with open(os.path.join(_ROOT, project["readme"]), encoding="utf-8") as f:
        return "\n".join(lines) + "\n\n" + f.read()


def _wheel_file(tag):
    return ("Wheel-Version: 1.0\nGenerator: octoprox_wheel\nRoot-Is-Purelib: %s\nTag: %s\n"
            % ("true" if tag.endswith("-any") else "false", tag))


def _library(config_settings):
    """The library to bundle (a path) or None."""
    path = (config_settings or {}).get("library") or os.environ.get("OPX_LIBRARY")
    if not path:
        return None
    if not os.path.isabs(path):
        raise ValueError("octoprox build: the library to bundle must be an absolute path (pip "
                         "builds in the package's folder), got %s" % path)
    path = os.path.realpath(path)
    if not os.path.isfile(path):
        raise FileNotFoundError("octoprox build: the library to bundle, %s, does not exist" % path)
    return path


def _check_library_version(path, version):
    """A library of another major.minor would fail at import: fail now."""
    number = ctypes.CDLL(path).opx_version_number()
    found = "%d.%d" % (number // 10000, number // 100 % 100)
    if found != ".".join(version.split(".")[:2]):
        raise ValueError("octoprox build: %s is version %s.%d, the package %s"
                         % (path, found, number % 100, version))


def _platform_tag():
    return sysconfig.get_platform().replace("-", "_").replace(".", "_")


def _package_files(c_sources=False):
    """(path in the archive, path on disk) of the package's sources: the
    Python files, and with ``c_sources`` (the sdist) the C ones."""
    folder = os.path.join(_ROOT, _PACKAGE)
    names = sorted(name for name in os.listdir(folder)
                   if name.endswith(".py") or name == "py.typed" or
                   (c_sources and name.endswith(".c")))
    return [(_PACKAGE + "/" + name, os.path.join(folder, name)) for name in names]


def _tag(library, with_extension):
    if with_extension:
        return extension.wheel_tag_prefix() + "-" + _platform_tag()
    return "py3-none-" + (_platform_tag() if library else "any")


def _build_extension(config_settings, scratch):
    """The compiled octoprox._fastcall in ``scratch``, or None (said why)."""
    reason = extension.why_not(config_settings)
    if reason is None:
        try:
            return extension.build(_ROOT, scratch)
        except OSError as error:
            reason = str(error)
    print("octoprox build: the wheel has no octoprox._fastcall (%s); the package uses ctypes "
          "alone" % reason, file=sys.stderr)
    return None


def _zip_time():
    # Reproducible archives: SOURCE_DATE_EPOCH, else the zip format's epoch.
    epoch = int(os.environ.get("SOURCE_DATE_EPOCH", 315532800))
    return time.gmtime(max(epoch, 315532800))[:6]


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return "%s,sha256=%s,%d" % (name, digest, len(data))


class _Wheel:
    def __init__(self, path):
        self.zip = zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED)
        self.records = []

    def add(self, name, data, mode=0o644):
        info = zipfile.ZipInfo(name, _zip_time())
        info.external_attr = (0o100000 | mode) << 16
        info.compress_type = zipfile.ZIP_DEFLATED
        self.zip.writestr(info, data)
        self.records.append(_record_line(name, data))

    def close(self, dist_info):
        record = dist_info + "/RECORD"
        self.records.append(record + ",,")
        self.add(record, ("\n".join(self.records) + "\n").encode())
        self.zip.close()


def _dist_info_files(project, tag):
    return {"METADATA": _metadata(project), "WHEEL": _wheel_file(tag), "top_level.txt": _PACKAGE + "\n"}


def _dist_name(project):
    return "%s-%s" % (project["name"], project["version"])


# ---- PEP 517 hooks --------------------------------------------------------

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    project = _project()
    tag = _tag(_library(config_settings), extension.why_not(config_settings) is None)
    dist_info = _dist_name(project) + ".dist-info"
    os.mkdir(os.path.join(metadata_directory, dist_info))
    for name, text in _dist_info_files(project, tag).items():
        with open(os.path.join(metadata_directory, dist_info, name), "w", encoding="utf-8") as f:
            f.write(text)
    return dist_info


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    project = _project()
    library = _library(config_settings)
    with tempfile.TemporaryDirectory() as scratch:
        module = _build_extension(config_settings, scratch)
        tag = _tag(library, module is not None)
        name = "%s-%s.whl" % (_dist_name(project), tag)
        wheel = _Wheel(os.path.join(wheel_directory, name))
        files = _package_files()
        if module:
            files.append((extension.archive_name(), module))
        for archive_name, path in files:
            with open(path, "rb") as f:
                wheel.add(archive_name, f.read(), 0o755 if path == module else 0o644)
    if library:
        _check_library_version(library, project["version"])
        with open(library, "rb") as f:
            wheel.add(_PACKAGE + "/" + _soname(project["version"]), f.read(), 0o755)
    else:
        print("octoprox build: OPX_LIBRARY is not set; the wheel uses the system's liboctoprox",
              file=sys.stderr)
    dist_info = _dist_name(project) + ".dist-info"
    for file_name, text in _dist_info_files(project, tag).items():
        wheel.add(dist_info + "/" + file_name, text.encode())
    wheel.close(dist_info)
    return name


def build_sdist(sdist_directory, config_settings=None):
    project = _project()
    base = _dist_name(project)
    name = base + ".tar.gz"
    files = [(path, os.path.join(_ROOT, path)) for path in _SDIST_FILES] + _package_files(True)
    with tarfile.open(os.path.join(sdist_directory, name), "w:gz", format=tarfile.PAX_FORMAT) as tar:
        for archive_name, path in files:
            tar.add(path, base + "/" + archive_name, recursive=False)
        info = tarfile.TarInfo(base + "/PKG-INFO")
        data = _metadata(project).encode()
        info.size = len(data)
        tar.addfile(info, io.BytesIO(data))
    return name
