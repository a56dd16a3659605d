"""The examples of docs/guide/scripting.md run, write their pictures, and print what
the page says they print."""

import numpy

import whitted
from docs_examples import ROOT, examples, run_all


def test_the_three_examples_run_and_write_their_pictures(tmp_path):
    assert len(examples()) == 3
    printed = run_all(tmp_path)
    for name, shape in [("reflectivity-sweep.png", (120, 800, 3)), ("field-40db.png", (240, 320, 3)),
                        ("float-1e0.png", (120, 160, 3)), ("float-1e19.png", (120, 160, 3))]:
        assert whitted.read_image(tmp_path / name).shape == shape, name
    assert "estimated" in printed[1]
    page = (ROOT / "docs" / "guide" / "scripting.md").read_text()
    for line in printed[2].splitlines():
        assert f"`{line}`" in page, line
    # The sweep's first frame is matte, its last a mirror: they differ.
    sheet = whitted.read_image(tmp_path / "reflectivity-sweep.png")
    assert not numpy.array_equal(sheet[:, :160], sheet[:, -160:])
