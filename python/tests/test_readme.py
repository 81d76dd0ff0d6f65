"""The README's Python block runs as written (from the repository root, its paths relative
to it), in a scratch directory holding a link to data/."""

from __future__ import annotations

import os
import re

from conftest import ROOT


def test_readme_python_block_runs(tmp_path, monkeypatch):
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(blocks) == 1, "one Python block in the README"
    (tmp_path / "data").symlink_to(ROOT / "data")
    monkeypatch.chdir(tmp_path)
    scope: dict = {}
    exec(compile(blocks[0], "README.md", "exec"), scope)
    assert float(scope["p"].max()) > 0.0
    # A run stops at the first step within half a step of its duration.
    summary = scope["sim"].summary
    assert summary["time"] >= 20.0 - 0.5 * summary["dt"]
    assert "kinetic_energy_change" in scope["sim"].summary
    assert (tmp_path / "tiny.nc").is_file()
    assert os.path.isdir(tmp_path / "runs" / "tiny" / "runs")
