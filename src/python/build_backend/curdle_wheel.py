"""A PEP 517 build backend for curdle's Python module: the project's CMake builds it, and the
wheel is made from what `cmake --install` lays out, with nothing fetched from the network.

The version is the one CMakeLists.txt's project() names, so that `curdle --version`, the
library and the wheel say the same. Hooks: build_wheel and get_requires_for_build_wheel (pip
needs no others to install from a source tree or to make a wheel)."""
import base64
import hashlib
import os
import re
import shutil
import stat
import subprocess
import sys
import sysconfig
import tempfile
import zipfile
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[3]


def _version():
    text = (SOURCE / "CMakeLists.txt").read_text(encoding="utf-8")
    return re.search(r"project\(curdle VERSION (\d+\.\d+\.\d+)", text).group(1)


def _tag():
    python = f"cp{sys.version_info.major}{sys.version_info.minor}"
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return f"{python}-{python}-{platform}"


def _run(*args):
    print("curdle_wheel:", " ".join(str(a) for a in args), flush=True)
    subprocess.run([str(a) for a in args], check=True)


def _build(settings):
    """The build tree, configured and built: the one named, or build/wheel."""
    named = (settings or {}).get("build-dir")
    build = Path(named).resolve() if named else SOURCE / "build" / "wheel"
    if not (build / "CMakeCache.txt").exists():
        _run("cmake", "-S", SOURCE, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
             "-DCURDLE_BUILD_TESTS=OFF", "-DCURDLE_PYTHON=ON",
             f"-DPython3_EXECUTABLE={sys.executable}")
    # The program, the server, the module, libcurdle.so and its image and GeoPackage modules.
    _run("cmake", "--build", build, "--parallel", str(os.cpu_count() or 2), "--target",
         "curdle_wheel_contents")
    return build


def _record_line(path, arcname):
    data = path.read_bytes()
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{arcname},sha256={digest},{len(data)}"


def get_requires_for_build_wheel(config_settings=None):
    return []


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    build = _build(config_settings)
    version = _version()
    name = f"curdle-{version}"
    with tempfile.TemporaryDirectory() as tmp:
        prefix = Path(tmp) / "prefix"
        _run("cmake", "--install", build, "--prefix", prefix)
        site = next(prefix.glob("lib/python3*/site-packages"))
        files = []  # (path on disk, name in the wheel)
        for path in sorted(site.rglob("*")):
            if path.is_file():
                files.append((path, path.relative_to(site).as_posix()))
        # Everything else is data under the prefix: libcurdle.so (which the module finds at
        # ../../../lib from site-packages/curdle), its modules, headers, the CMake package, the
        # patterns and the page; and the programs.
        for path in sorted(prefix.rglob("*")):
            if not path.is_file() or site in path.parents:
                continue
            inside = path.relative_to(prefix).as_posix()
            # Programs as scripts: pip installs them into the prefix's bin, executable.
            where = f"scripts/{path.name}" if inside.startswith("bin/") else f"data/{inside}"
            files.append((path, f"{name}.data/{where}"))
        dist = f"{name}.dist-info"
        meta = Path(tmp) / "meta"
        meta.mkdir()
        (meta / "METADATA").write_text(
            "Metadata-Version: 2.1\n"
            f"Name: curdle\nVersion: {version}\n"
            "Summary: Random curds for facade, paving, perforation and park layouts\n"
            "License: GPL-3.0-or-later\nRequires-Python: >=3.11\nRequires-Dist: numpy\n",
            encoding="utf-8")
        (meta / "WHEEL").write_text(
            "Wheel-Version: 1.0\nGenerator: curdle_wheel\nRoot-Is-Purelib: false\n"
            f"Tag: {_tag()}\n", encoding="utf-8")
        shutil.copy(SOURCE / "LICENSE", meta / "LICENSE")
        for path in sorted(meta.iterdir()):
            files.append((path, f"{dist}/{path.name}"))
        wheel = f"{name}-{_tag()}.whl"
        records = [_record_line(path, arcname) for path, arcname in files]
        records.append(f"{dist}/RECORD,,")
        # The fastest deflate: the libraries shrink little more at higher levels.
        with zipfile.ZipFile(Path(wheel_directory) / wheel, "w", zipfile.ZIP_DEFLATED,
                             compresslevel=1) as z:
            for path, arcname in files:
                info = zipfile.ZipInfo(arcname, date_time=(2000, 1, 1, 0, 0, 0))
                info.external_attr = (stat.S_IFREG | (path.stat().st_mode & 0o777)) << 16
                info.compress_type = zipfile.ZIP_DEFLATED
                z.writestr(info, path.read_bytes(), compresslevel=1)
            z.writestr(f"{dist}/RECORD", "\n".join(records) + "\n")
    return wheel
