"""Shared pytest options.

``--update-golden``: tests that compare output with a golden file rewrite the
golden file instead (review the diff before committing it).

The cache of compiled blocks that ``spinemu run`` keeps between runs goes to a
temporary directory of the test session, not to the user's ~/.cache.
"""
import os
import tempfile

import pytest

os.environ.setdefault("SPINEMU_CACHE_DIR", tempfile.mkdtemp(prefix="spinemu-test-cache-"))


def pytest_addoption(parser):
    parser.addoption("--update-golden", action="store_true", default=False,
                     help="rewrite golden files (listings, disassembly) instead of comparing with them")


@pytest.fixture
def update_golden(request) -> bool:
    """True when the run was started with ``--update-golden``."""
    return request.config.getoption("--update-golden")
