# SPDX-License-Identifier: Apache-2.0
"""docs/python.md's examples, run in order in one namespace, in an empty folder."""
import re
from pathlib import Path

DOC = Path(__file__).resolve().parents[2] / "docs" / "python.md"


def test_every_example_of_the_tutorial_runs(tmp_path, monkeypatch, capsys):
    blocks = re.findall(r"```python\n(.*?)```", DOC.read_text(), flags=re.S)
    assert len(blocks) >= 4, "the tutorial's examples"
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for k, block in enumerate(blocks):
        exec(compile(block, f"{DOC.name} example {k + 1}", "exec"), namespace)
    out = capsys.readouterr().out
    assert "min-area must be in [0, 1), got 2" in out
    for written in ["room.vtp", "inside.png", "room-reference/reference.vtp",
                    "room-study/table.json", "room-study.png", "cornell.vtp"]:
        assert (tmp_path / written).stat().st_size > 0, written
