"""Shared helpers: the path of the molchaos program under test."""

import os

import pytest


@pytest.fixture(scope="session")
def molchaos_bin():
    path = os.environ.get("MOLCHAOS_BIN", "build/molchaos")
    assert os.access(path, os.X_OK), f"molchaos program not found at {path}"
    return path
