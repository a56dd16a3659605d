"""The Whitted ray tracer from Python.

Load or build a scene, change it, render it into a NumPy array, write or
compare images::

    import whitted
    scene = whitted.load("scenes/seed.json")
    scene.spheres[0].radius = 0.8
    image = whitted.render(scene, width=320, height=240)   # float32 (240, 320, 3), linear
    whitted.write_image(image, "seed.png")

docs/guide/scripting.md has more examples; help(whitted.render) lists every setting.
"""

import os
import tempfile

import numpy

from ._whitted import (
    Camera,
    Checker,
    Comparison,
    Light,
    LightList,
    Material,
    MaterialList,
    RenderSettings,
    Scene,
    Sphere,
    SphereList,
    compare,
    field,
    load,
    load_dict,
    read_image,
    turntable,
    write_image,
)
from . import _whitted

__all__ = [
    "Camera", "Checker", "Comparison", "Image", "Light", "Material", "RenderSettings", "Scene",
    "Sphere", "compare", "field", "load", "load_dict", "read_image", "render", "turntable",
    "write_image",
]


class Image(numpy.ndarray):
    """A rendered picture: a float32 array of shape (height, width, 3) holding
    linear RGB, which a notebook shows as the sRGB PNG that write_image() writes."""

    def _repr_png_(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "image.png")
            write_image(numpy.asarray(self), path)
            with open(path, "rb") as png:
                return png.read()


def render(scene, **settings):
    result = _whitted.render(scene, **settings)
    if settings.get("return_stats"):
        image, stats = result
        return image.view(Image), stats
    return result.view(Image)


render.__doc__ = _whitted.render.__doc__
