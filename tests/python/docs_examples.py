"""The Python examples of docs/guide/scripting.md: each run in a folder, from which
the project's scenes/ is reachable, so that the pictures they write land
there. `python3 tests/python/docs_examples.py FOLDER` writes them to FOLDER
(docs/images/python for the docs); tests/python/test_docs.py runs them."""

import contextlib
import io
import os
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def examples():
    text = (ROOT / "docs" / "guide" / "scripting.md").read_text()
    return re.findall(r"```python\n(.*?)```", text, re.S)


def run_all(folder):
    """Runs every example in `folder`; returns what each printed."""
    folder = pathlib.Path(folder).resolve()
    folder.mkdir(parents=True, exist_ok=True)
    scenes = folder / "scenes"
    if not scenes.exists():
        scenes.symlink_to(ROOT / "scenes")
    printed = []
    here = os.getcwd()
    os.chdir(folder)
    try:
        for code in examples():
            out = io.StringIO()
            with contextlib.redirect_stdout(out):
                exec(compile(code, "docs/guide/scripting.md", "exec"), {"__name__": "__example__"})
            printed.append(out.getvalue())
    finally:
        os.chdir(here)
        scenes.unlink()
    return printed


if __name__ == "__main__":
    for output in run_all(sys.argv[1] if len(sys.argv) > 1 else "."):
        sys.stdout.write(output)
