"""Renders from Python equal whitted-render's, bit for bit, and say what
whitted-render --stats says."""

import json
import subprocess

import numpy
import pytest

import whitted
from conftest import SHIPPED


def render_with_the_program(bin_dir, scene_path, out, *flags):
    subprocess.run([bin_dir / "whitted-render", scene_path, "-o", out, "--quiet", *flags],
                   check=True)
    return whitted.read_image(out)


@pytest.mark.parametrize("precision", ["float", "double"])
@pytest.mark.parametrize("scene_path", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_every_shipped_scene_equals_whitted_render_bit_for_bit(bin_dir, tmp_path, scene_path,
                                                               precision):
    size = dict(width=96, height=72)
    image = whitted.render(whitted.load(scene_path), precision=precision, **size)
    assert image.dtype == numpy.float32 and image.shape == (72, 96, 3)
    expected = render_with_the_program(bin_dir, scene_path, tmp_path / "out.exr", "--width",
                                       "96", "--height", "72", "--precision", precision)
    assert numpy.array_equal(image, expected)


def test_samples_depth_and_a_region_as_the_program_renders_them(bin_dir, tmp_path, seed_path):
    scene = whitted.load(seed_path)
    image = whitted.render(scene, width=80, height=60, spp=4, depth=3, region=(10, 20, 50, 45))
    assert image.shape == (25, 40, 3)
    expected = render_with_the_program(bin_dir, seed_path, tmp_path / "part.exr", "--width", "80",
                                       "--height", "60", "--spp", "4", "--depth", "3",
                                       "--region", "10,20,50,45")
    assert numpy.array_equal(image, expected)


def test_a_quality_target_and_its_stats_as_the_program_gives_them(bin_dir, tmp_path, seed_path):
    image, stats = whitted.render(whitted.load(seed_path), width=64, height=48, quality="draft",
                                  return_stats=True)
    expected = render_with_the_program(bin_dir, seed_path, tmp_path / "q.exr", "--width", "64",
                                       "--height", "48", "--quality", "draft", "--stats",
                                       tmp_path / "q.json")
    assert numpy.array_equal(image, expected)
    program = json.loads((tmp_path / "q.json").read_text())
    for key in ("width", "height", "samples_per_pixel", "max_depth", "precision", "rays"):
        assert stats[key] == program[key], key
    assert stats["quality"]["target"] == program["quality"]["target"]


def test_the_scenes_own_settings_are_left_as_they_were(seed_path):
    scene = whitted.load(seed_path)
    whitted.render(scene, width=16, height=12, precision="double", depth=0)
    assert (scene.render.width, scene.render.precision, scene.render.max_depth) == (640, "float", 2)


@pytest.mark.parametrize("settings, message", [
    (dict(width=0), r"width must be in \[1, 16384\]"),
    (dict(precision="half"), r"precision must be"),
    (dict(quality="best"), r"quality must be"),
    (dict(quality="draft", target_psnr=30), r"give one or the other"),
    (dict(max_error=4), r"max_error needs target_psnr"),
    (dict(region=(0, 0, 700, 10)), r"not a part of the 640x480 image"),
])
def test_bad_settings_raise_value_error(seed_path, settings, message):
    with pytest.raises(ValueError, match=message):
        whitted.render(whitted.load(seed_path), **settings)


def test_an_estimate_of_no_error_at_all_is_infinity_not_none():
    # Nothing but the background: every sample agrees, so the estimate has no
    # error; the stats file says null (JSON has no infinity), Python says inf.
    empty = whitted.load_dict({"camera": {"position": [0, 1, -5], "look_at": [0, 1, 0]},
                               "render": {"width": 32, "height": 24},
                               "materials": [], "lights": [], "spheres": []})
    _, stats = whitted.render(empty, quality="final", return_stats=True)
    assert stats["quality"]["estimated_psnr_db"] == float("inf")
