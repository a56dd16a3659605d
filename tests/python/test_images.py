"""Images in and out, their comparison, whitted-field's scenes and turntables."""

import subprocess

import numpy
import pytest

import whitted


def test_write_and_read_back_every_format(tmp_path, seed_path):
    image = whitted.render(whitted.load(seed_path), width=40, height=30)
    for ext in ("exr", "hdr", "tif", "png", "jpg"):
        path = tmp_path / f"out.{ext}"
        whitted.write_image(image, path)
        back = whitted.read_image(path)
        assert back.shape == image.shape, ext
        if ext == "exr":
            assert numpy.array_equal(back, image)
        elif ext == "png":
            # 8 bits with the sRGB curve: within half a code of each value.
            assert whitted.compare(back, image).largest_error <= 0.5


def test_a_bad_path_or_shape_raises_value_error_naming_it(tmp_path):
    with pytest.raises(ValueError, match=r"out\.bmpx: unknown image extension"):
        whitted.write_image(numpy.zeros((4, 4, 3), numpy.float32), tmp_path / "out.bmpx")
    with pytest.raises(ValueError, match=r"shape \(height, width, 3\), not \(4, 4\)"):
        whitted.write_image(numpy.zeros((4, 4)), tmp_path / "out.png")
    assert not list(tmp_path.iterdir())


def test_compare_gives_the_psnr_and_largest_error_in_codes():
    a = numpy.full((10, 10, 3), 0.5, numpy.float32)
    b = a.copy()
    assert whitted.compare(a, b).psnr == float("inf")
    b[3, 4] = (1.0, 0.5, 0.5)  # sRGB codes 188 against 255 in one channel of one pixel
    result = whitted.compare(b, a)
    assert result.largest_error == pytest.approx(67, abs=0.5)
    mse = 67.0 ** 2 / 300
    assert result.psnr == pytest.approx(10 * numpy.log10(255 ** 2 / mse), abs=0.2)


def test_field_is_the_scene_whitted_field_writes(bin_dir, tmp_path):
    out = tmp_path / "field.json"
    subprocess.run([bin_dir / "whitted-field", "250", "--seed", "7", "-o", out], check=True)
    assert whitted.field(250, seed=7) == whitted.load(out)
    assert len(whitted.field(250, seed=7).spheres) == 251


def test_turntable_cameras_render_as_the_programs_frames(bin_dir, tmp_path, seed_path):
    scene = whitted.load(seed_path)
    cameras = whitted.turntable(scene, 4)
    assert len(cameras) == 4 and cameras[0] == scene.camera
    subprocess.run([bin_dir / "whitted-render", seed_path, "-o", tmp_path / "turn.exr",
                    "--width", "32", "--height", "24", "--turntable", "4", "--quiet"], check=True)
    frames = sorted(tmp_path.glob("turn*.exr"))
    assert len(frames) == 4
    for camera, frame in zip(cameras, frames):
        scene.camera = camera
        assert numpy.array_equal(whitted.render(scene, width=32, height=24),
                                 whitted.read_image(frame)), frame.name


def test_a_rendered_image_shows_itself_as_a_png(seed_path):
    image = whitted.render(whitted.load(seed_path), width=20, height=10)
    png = image._repr_png_()
    assert png.startswith(b"\x89PNG\r\n\x1a\n")
