"""Shared fixtures of the Python package's tests (pytest, run by CTest: tests/CMakeLists.txt sets
PYTHONPATH to the build's package, SIGNORINI_TOOL to the command-line tool and
SIGNORINI_SOURCE_DIR to the repository)."""

import os
import pathlib

import pytest

SOURCE = pathlib.Path(os.environ.get("SIGNORINI_SOURCE_DIR",
                                     pathlib.Path(__file__).resolve().parents[2]))
TOOL = os.environ.get("SIGNORINI_TOOL", str(SOURCE / "build/release/app/signorini"))


@pytest.fixture
def examples():
    return SOURCE / "examples"


@pytest.fixture
def tool():
    return TOOL
