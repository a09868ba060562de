"""Shared fixtures of the Python tests: the repository's example meshes."""
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture
def examples():
    return ROOT / "examples"


@pytest.fixture
def repo_root():
    return ROOT
