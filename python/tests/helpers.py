"""Paths the Python tests share. ctest sets the environment (python/CMakeLists.txt); run by hand
from the repository root:
    PYTHONPATH=build/python BIMDF_CLI=build/bin/bimdf python3 -m pytest python/tests -q
"""

import os
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"
BUNNY_LAYOUT = EXAMPLES / "npm_bunny" / "npm_bunny.obj"
BUNNY_PROBLEM = EXAMPLES / "npm_bunny__flow_noalign_lemon_0.bimdf"


def cli() -> Path:
    """The built bimdf CLI (BIMDF_CLI, default build/bin/bimdf)."""
    path = Path(os.environ.get("BIMDF_CLI", REPO / "build" / "bin" / "bimdf"))
    if not path.is_absolute():
        path = (Path.cwd() / path).resolve()
    if not (path.is_file() and os.access(path, os.X_OK)):
        pytest.skip(f"bimdf CLI not built at {path} (set BIMDF_CLI)")
    return path


def shared_data(sub: str) -> Path:
    """A folder of ../shared/data (BIMDF_SHARED_DATA_DIR); skips where a clone has none."""
    data = Path(os.environ.get("BIMDF_SHARED_DATA_DIR", REPO.parent / "shared" / "data"))
    folder = data / sub
    if not folder.is_dir():
        pytest.skip(f"shared data folder {folder} is absent (set BIMDF_SHARED_DATA_DIR)")
    return folder


def run_cli(*args, check=True) -> subprocess.CompletedProcess:
    return subprocess.run([str(cli()), *map(str, args)], capture_output=True, text=True,
                          check=check, timeout=600)
