"""Shared by the Python module's tests: where the scenes and programs are.

ctest runs these with PYTHONPATH=build/python and WHITTED_BIN=build/bin
(tests/CMakeLists.txt); `pytest tests/python` from the build's environment
does the same."""

import os
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENES = ROOT / "scenes"
SHIPPED = sorted(SCENES.rglob("*.json"))  # with scenes/extremes/


@pytest.fixture
def bin_dir():
    return pathlib.Path(os.environ.get("WHITTED_BIN", ROOT / "build" / "bin"))


@pytest.fixture
def seed_path():
    return SCENES / "seed.json"
