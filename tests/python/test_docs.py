"""docs/python.md runs: its python blocks, in order and in one namespace, in a temporary folder
holding a copy of examples/, so the tutorial cannot drift from the module."""
import re
import shutil


def python_blocks(markdown):
    return re.findall(r"^```python\n(.*?)^```", markdown, re.MULTILINE | re.DOTALL)


def test_python_md_runs(repo_root, tmp_path, monkeypatch):
    blocks = python_blocks((repo_root / "docs" / "python.md").read_text())
    assert len(blocks) >= 8  # a lost fence would silently skip the blocks after it
    shutil.copytree(repo_root / "examples", tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    namespace = {"__name__": "python_md"}
    for number, block in enumerate(blocks, 1):
        exec(compile(block, f"docs/python.md, python block {number}", "exec"), namespace)
    assert (tmp_path / "holed_smooth.obj").is_file() and (tmp_path / "samples.ply").is_file()
