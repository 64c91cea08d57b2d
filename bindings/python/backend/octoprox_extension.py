"""Compiles octoprox._fastcall (octoprox/_fastcall.c) for the interpreter
running the build, with its own compiler settings (sysconfig's LDSHARED,
CCSHARED and include directory), for octoprox_wheel to put in the wheel.

The module links no library and needs only Python.h (Debian: python3-dev)
and a C compiler.  Where either is missing, or with ``pip wheel
--config-settings extension=no`` (``-C extension=no`` from pip 23.1), the
wheel is built without it and the package calls the library through ctypes
alone (the same answers, slower small queries).
"""
import os
import shlex
import subprocess
import sys
import sysconfig

SOURCE = os.path.join("octoprox", "_fastcall.c")


def archive_name():
    """The module's path in the wheel, e.g.
    octoprox/_fastcall.cpython-311-x86_64-linux-gnu.so."""
    return "octoprox/_fastcall" + sysconfig.get_config_var("EXT_SUFFIX")


def wheel_tag_prefix():
    """The interpreter and ABI tags of a wheel carrying the module, e.g.
    cp311-cp311."""
    version = "cp%d%d" % sys.version_info[:2]
    return version + "-" + version


def why_not(config_settings):
    """Why the module cannot be built here (a sentence), or None."""
    if (config_settings or {}).get("extension", "auto") == "no":
        return "left out (--config-settings extension=no)"
    if sys.implementation.name != "cpython":
        return "not CPython (%s)" % sys.implementation.name
    include = sysconfig.get_paths()["include"]
    if not os.path.exists(os.path.join(include, "Python.h")):
        return "no %s/Python.h (Debian: python3-dev)" % include
    if not sysconfig.get_config_var("EXT_SUFFIX"):
        return "this Python names no extension suffix"
    return None


def _command(source, output):
    linker = sysconfig.get_config_var("LDSHARED") or \
        (sysconfig.get_config_var("CC") or "cc") + " -shared"
    shared = sysconfig.get_config_var("CCSHARED") or "-fPIC"
    return (shlex.split(linker) + shlex.split(shared) +
            ["-O2", "-fvisibility=hidden", "-I", sysconfig.get_paths()["include"], source,
             "-o", output])


def build(root, directory):
    """The compiled module's path in ``directory`` (a scratch folder), or
    raises OSError with the compiler's message."""
    output = os.path.join(directory, os.path.basename(archive_name()))
    command = _command(os.path.join(root, SOURCE), output)
    try:
        run = subprocess.run(command, capture_output=True, text=True)
    except OSError as error:
        raise OSError("%s: %s" % (command[0], error)) from None
    if run.returncode != 0:
        raise OSError("%s failed:\n%s" % (" ".join(command), run.stderr.strip()))
    return output
