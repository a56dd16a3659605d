"""Scenes from Python: loaded, changed in place, saved and read back, and
refused with the file loader's messages."""

import json
import os
import pathlib

import pytest

import whitted
from conftest import SHIPPED


def test_load_gives_the_files_values_as_attributes(seed_path):
    scene = whitted.load(seed_path)
    text = json.loads(seed_path.read_text())
    assert len(scene.spheres) == len(text["spheres"])
    assert scene.spheres[0].name == text["spheres"][0]["name"]
    assert scene.spheres[0].center == tuple(text["spheres"][0]["center"])
    assert scene.camera.vfov_degrees == text["camera"]["vfov_degrees"]
    assert scene.render.precision == "float"
    assert scene.materials[3].checker.size == 0.5


def test_lists_change_the_scene_in_place_and_save_reads_back(seed_path, tmp_path):
    scene = whitted.load(seed_path)
    scene.spheres[0].radius = 0.8
    scene.spheres[0].center = [1, 2, 3]
    scene.spheres.append(whitted.Sphere("new ball", center=(0, 1, 4), radius=0.3, material="blue"))
    scene.lights[0].intensity = 0.5
    scene.render.precision = "double"
    out = tmp_path / "changed.json"
    scene.save(out)
    back = whitted.load(out)
    assert back == scene
    assert back.spheres[0].radius == 0.8
    assert back.spheres[0].center == (1.0, 2.0, 3.0)
    assert back.spheres[-1].name == "new ball"
    assert back.render.precision == "double"


def test_a_list_given_to_a_scene_replaces_its_items(seed_path):
    scene = whitted.load(seed_path)
    scene.spheres = [whitted.Sphere("only ball", center=(0, 0.5, 3), radius=0.5, material="blue")]
    scene.lights = list(scene.lights) + [whitted.Light("fill", position=(-5, 3, -5), intensity=0.3)]
    assert [s.name for s in scene.spheres] == ["only ball"]
    assert [l.name for l in scene.lights] == ["key", "fill"]
    assert whitted.render(scene, width=16, height=12).shape == (12, 16, 3)


def test_to_dict_and_load_dict_round_trip_every_shipped_scene():
    for path in SHIPPED:
        scene = whitted.load(path)
        assert whitted.load_dict(scene.to_dict()) == scene, path.name


def test_a_bad_value_raises_value_error_naming_the_field(seed_path):
    d = whitted.load(seed_path).to_dict()
    d["spheres"][0]["radius"] = -1
    with pytest.raises(ValueError, match=r"^spheres\[0\]\.radius: must be > 0"):
        whitted.load_dict(d)
    d = whitted.load(seed_path).to_dict()
    d["spheres"][1]["material"] = "chrome"
    with pytest.raises(ValueError, match=r"^spheres\[1\]\.material: "):
        whitted.load_dict(d)


def test_a_bad_file_names_the_file_and_the_field(seed_path, tmp_path):
    d = json.loads(seed_path.read_text())
    d["render"]["width"] = 0
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(d))
    with pytest.raises(ValueError, match=r"bad\.json: render\.width: "):
        whitted.load(bad)
    with pytest.raises(FileNotFoundError):
        whitted.load(tmp_path / "missing.json")


def test_a_scene_made_invalid_in_python_is_refused_by_render_and_save(seed_path, tmp_path):
    scene = whitted.load(seed_path)
    scene.spheres[2].radius = 0
    with pytest.raises(ValueError, match=r"^spheres\[2\]\.radius: must be > 0"):
        whitted.render(scene, width=8, height=8)
    out = tmp_path / "never.json"
    with pytest.raises(ValueError, match=r"^spheres\[2\]\.radius"):
        scene.save(out)
    assert not out.exists()


def bad_scene_cases():
    """The scene-file tests' bad cases (tests/core/test_scene_io.cpp), as the
    fixture bad_scenes writes them: text, file message, field message."""
    path = os.environ.get("WHITTED_BAD_SCENES")
    if not path:
        pytest.fail("WHITTED_BAD_SCENES is not set: run through ctest, which writes the cases")
    with open(path) as cases:
        return json.load(cases)


def test_every_bad_case_of_the_scene_file_tests_raises_their_message(tmp_path, monkeypatch):
    cases = bad_scene_cases()
    assert len(cases) > 50
    monkeypatch.chdir(tmp_path)
    for case in cases:
        pathlib.Path("bad scene.json").write_text(case["text"])
        with pytest.raises(ValueError) as refused:
            whitted.load("bad scene.json")
        assert str(refused.value) == case["message"], case["what"]
        # As a dict: the same field and reason. Not where the dict cannot say
        # what the file did: format and version, which load_dict fills in, and
        # infinite numbers, which JSON has no word for.
        if "missing" in case["what"] and ("format" in case["what"] or "version" in case["what"]):
            continue
        if "1e999" in case["text"]:
            continue
        with pytest.raises(ValueError) as refused:
            whitted.load_dict(json.loads(case["text"]))
        assert str(refused.value) == case["field"], case["what"]
