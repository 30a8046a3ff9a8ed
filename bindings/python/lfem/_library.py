"""Finds and loads liblfem. The first place that holds a library of this version wins:

1. LFEM_LIBRARY: the library file, or a folder holding it;
2. the build folder of the source checkout this package sits in (build/ at its root), when it
   is run from the checkout;
3. the library folder of the prefix that `cmake --install` put this package into (the file
   _install_paths.py, written by the install, says where it is from here);
4. the libdir that pkg-config gives for lfem (so PKG_CONFIG_PATH=<prefix>/lib/pkgconfig finds
   an lfem installed anywhere);
5. the versioned soname through the dynamic loader's own search (LD_LIBRARY_PATH, ld.so.cache:
   an lfem installed into /usr/local needs nothing).

The versioned name (liblfem.so.0, the SONAME) comes first everywhere: it is the name a runtime
install always has, and it cannot pick a library of another major version.
"""

from __future__ import annotations

import ctypes
import os
import shutil
import subprocess
import sys
from typing import Iterator, List, Optional, Tuple

from ._version import __version__

_MAJOR, _MINOR = (int(part) for part in __version__.split(".")[:2])


def file_names() -> List[str]:
    """The library's file names on this platform, the versioned one first."""
    if sys.platform == "darwin":
        return ["liblfem.%d.dylib" % _MAJOR, "liblfem.dylib"]
    if sys.platform == "win32":
        return ["lfem.dll"]
    return ["liblfem.so.%d" % _MAJOR, "liblfem.so"]


def _in_folder(folder: str) -> Optional[str]:
    for name in file_names():
        path = os.path.join(folder, name)
        if os.path.exists(path):
            return path
    return None


def _pkg_config_libdir() -> Tuple[Optional[str], str]:
    """(libdir, "") from `pkg-config --variable=libdir lfem`, or (None, why not)."""
    exe = os.environ.get("PKG_CONFIG") or shutil.which("pkg-config") or shutil.which("pkgconf")
    if not exe:
        return None, "no pkg-config program"
    try:
        run = subprocess.run([exe, "--variable=libdir", "lfem"], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, universal_newlines=True, timeout=60)
    except (OSError, subprocess.SubprocessError) as e:
        return None, "%s failed: %s" % (exe, e)
    if run.returncode != 0 or not run.stdout.strip():
        return None, "no lfem.pc on its search path (PKG_CONFIG_PATH)"
    return run.stdout.strip(), ""


def _candidates() -> Iterator[Tuple[str, Optional[str], str]]:
    """(where, path or None, why none) in the order of the module docstring."""
    env = os.environ.get("LFEM_LIBRARY")
    if env:
        path = _in_folder(env) if os.path.isdir(env) else env
        yield "LFEM_LIBRARY=" + env, path, "a folder without " + " or ".join(file_names())
        return  # named explicitly: nothing else is tried
    package = os.path.dirname(os.path.abspath(__file__))
    checkout = os.path.normpath(os.path.join(package, os.pardir, os.pardir, os.pardir))
    if os.path.exists(os.path.join(checkout, "include_c", "lfem.h")):
        build = os.path.join(checkout, "build")
        yield "the checkout's build folder " + build, _in_folder(build), "not built"
    try:
        from . import _install_paths  # type: ignore[attr-defined]  # written by cmake --install
    except ImportError:
        pass
    else:
        libdir = os.path.normpath(os.path.join(package, _install_paths.LIBDIR_FROM_PACKAGE))
        yield "the install prefix's " + libdir, _in_folder(libdir), "no library there"
    libdir, why = _pkg_config_libdir()
    if libdir is not None:
        yield "pkg-config's libdir " + libdir, _in_folder(libdir), "no library there"
    else:
        yield "pkg-config lfem", None, why
    # A bare name: dlopen searches LD_LIBRARY_PATH, the ld.so cache and the default folders.
    yield "the dynamic loader's search path", file_names()[0], ""


def _loaded_path(path: str) -> str:
    """The file behind a bare soname that the loader found (from /proc/self/maps on Linux)."""
    if os.path.isabs(path) or not os.path.exists("/proc/self/maps"):
        return path
    with open("/proc/self/maps") as maps:
        for line in maps:
            fields = line.split(None, 5)
            if len(fields) == 6 and os.path.basename(fields[5].strip()).startswith("liblfem.so"):
                return fields[5].strip()
    return path


def load() -> Tuple[ctypes.CDLL, str]:
    """The loaded library and its path; OSError listing every place tried when none fits."""
    tried = []
    for where, path, why in _candidates():
        if path is None:
            tried.append("%s: %s" % (where, why))
            continue
        try:
            lib = ctypes.CDLL(path)
        except OSError as e:
            tried.append("%s: %s" % (where, e))
            continue
        lib.lfem_version.restype = ctypes.c_uint32
        lib.lfem_version.argtypes = []
        v = lib.lfem_version()
        major, minor = v >> 16, (v >> 8) & 0xFF
        # 0.x releases may break the ABI at each minor version (lfemConfigVersion.cmake:
        # SameMinorVersion), so both must match.
        if major != _MAJOR or (_MAJOR == 0 and minor != _MINOR):
            tried.append("%s: %s is version %d.%d, these bindings need %d.%d"
                         % (where, path, major, minor, _MAJOR, _MINOR))
            continue
        return lib, _loaded_path(path)
    raise OSError("lfem %s (Python): liblfem not found. Tried:\n  %s\nInstall lfem "
                  "(cmake --install <build> --prefix <prefix>) and set "
                  "PKG_CONFIG_PATH=<prefix>/lib/pkgconfig, or set LFEM_LIBRARY to the library."
                  % (__version__, "\n  ".join(tried)))
