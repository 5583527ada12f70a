"""The harness examples in README.md and docs/testing.md run as shown."""
import re
from pathlib import Path

import spinemu.testing
from spinemu.testing.plugin import SpinFixture

ROOT = Path(__file__).parent.parent.parent


def python_blocks(path):
    return re.findall(r"```python\n(.*?)```", path.read_text(), re.S)


def test_the_readme_harness_example_passes(monkeypatch):
    monkeypatch.chdir(ROOT)
    (block,) = [b for b in python_blocks(ROOT / "README.md") if "def test_counted_steps(spin)" in b]
    namespace: dict = {}
    exec(block, namespace)
    namespace["test_counted_steps"](SpinFixture([]))


def test_the_first_example_of_docs_testing_runs(monkeypatch):
    monkeypatch.chdir(ROOT)
    block = python_blocks(ROOT / "docs" / "testing.md")[0]
    namespace: dict = {"spinemu": spinemu}
    exec(block.replace("print(motor.where())", "where = motor.where()"), namespace)
    assert namespace["where"][1].startswith("cog 1 (running): runStepper(m1=1) at")
