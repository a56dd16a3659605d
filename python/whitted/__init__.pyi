# Type stubs of the whitted package, for editors and type checkers.
# Units: positions and sizes in scene units (y up); colours linear RGB.
from os import PathLike
from typing import Any, Callable, Iterable, Literal, MutableSequence, Optional, Sequence, overload

import numpy
import numpy.typing

Vec3 = tuple[float, float, float]
Vec3Like = Sequence[float]
Path = str | PathLike[str]
FloatImage = numpy.typing.NDArray[numpy.float32]

class Checker:
    color: Vec3
    """Linear RGB of the other cells, each in [0, 1]."""
    size: float
    """Edge of a cell, > 0."""
    def __init__(self, color: Vec3Like = ..., size: float = 1.0) -> None: ...

class Material:
    name: str
    diffuse: Vec3
    """Linear RGB, each in [0, 1]."""
    specular: float
    """Highlight strength ks, >= 0."""
    shininess: float
    """Phong exponent, >= 0."""
    reflectivity: float
    """kr in [0, 1]."""
    transparency: float
    """kt in [0, 1]; also what shadows let through."""
    ior: float
    """Index of refraction, > 0."""
    checker: Optional[Checker]
    def __init__(self, name: str, diffuse: Vec3Like = ..., specular: float = 0.0,
                 shininess: float = 50.0, reflectivity: float = 0.0, transparency: float = 0.0,
                 ior: float = 1.5, checker: Optional[Checker] = None) -> None: ...

class Light:
    name: str
    position: Vec3
    color: Vec3
    """Linear RGB, each >= 0."""
    intensity: float
    """Multiplies color, >= 0; no fall-off with distance."""
    def __init__(self, name: str, position: Vec3Like = ..., color: Vec3Like = ...,
                 intensity: float = 1.0) -> None: ...

class Sphere:
    name: str
    center: Vec3
    radius: float
    """> 0."""
    material: str
    """The name of one of the scene's materials."""
    def __init__(self, name: str, center: Vec3Like = ..., radius: float = 1.0,
                 material: str = "") -> None: ...

class Camera:
    position: Vec3
    look_at: Vec3
    up: Vec3
    vfov_degrees: float
    """Vertical field of view, in (0, 180)."""
    def __init__(self, position: Vec3Like = ..., look_at: Vec3Like = ..., up: Vec3Like = ...,
                 vfov_degrees: float = 60.0) -> None: ...

class RenderSettings:
    width: int
    """1 to 16384 pixels."""
    height: int
    """1 to 16384 pixels."""
    max_depth: int
    """0 to 64 bounces."""
    samples_per_pixel: int
    """1 to 65536."""
    precision: Literal["float", "double"]

# The scene's own lists: indexing, append, extend, insert, pop, del and len as
# a list's; a slice is a copy; no +. A plain list may be assigned in their place.
class SphereList(MutableSequence[Sphere]): ...
class LightList(MutableSequence[Light]): ...
class MaterialList(MutableSequence[Material]): ...

class Scene:
    camera: Camera
    render: RenderSettings
    background: Vec3
    ambient: Vec3
    materials: MaterialList | list[Material]
    lights: LightList | list[Light]
    spheres: SphereList | list[Sphere]
    """Changed in place: scene.spheres[0].radius = 2 changes the scene."""
    def __init__(self) -> None: ...
    def save(self, path: Path) -> None:
        """Writes the scene file atomically. Raises ValueError naming the field."""
    def to_dict(self) -> dict[str, Any]: ...
    def copy(self) -> Scene: ...

class Comparison:
    psnr: float
    """dB of the 8-bit sRGB pictures (peak 255); inf when identical."""
    largest_error: float
    """The largest difference of a pixel, in 8-bit codes."""
    rmse: float
    psnr_linear: float
    rmse_linear: float

class Image(numpy.ndarray):
    """A render: float32 (height, width, 3), linear RGB; shows itself in a notebook."""
    def _repr_png_(self) -> bytes: ...

def load(path: Path) -> Scene:
    """Reads a scene file. Raises FileNotFoundError, or ValueError naming the file and field."""
def load_dict(d: dict[str, Any]) -> Scene:
    """A scene from a dict in the file's form. Raises ValueError naming the field."""

@overload
def render(scene: Scene, *, width: Optional[int] = None, height: Optional[int] = None,
           spp: Optional[int] = None, depth: Optional[int] = None,
           precision: Optional[Literal["float", "double"]] = None, threads: int = 0,
           quality: Optional[Literal["draft", "preview", "final"]] = None,
           target_psnr: Optional[float] = None, max_error: Optional[float] = None,
           region: Optional[tuple[int, int, int, int]] = None,
           return_stats: Literal[False] = False,
           progress: Optional[Callable[[float], None]] = None) -> Image:
    """Renders as whitted-render does; see help(whitted.render)."""
@overload
def render(scene: Scene, *, width: Optional[int] = None, height: Optional[int] = None,
           spp: Optional[int] = None, depth: Optional[int] = None,
           precision: Optional[Literal["float", "double"]] = None, threads: int = 0,
           quality: Optional[Literal["draft", "preview", "final"]] = None,
           target_psnr: Optional[float] = None, max_error: Optional[float] = None,
           region: Optional[tuple[int, int, int, int]] = None,
           return_stats: Literal[True] = ...,
           progress: Optional[Callable[[float], None]] = None) -> tuple[Image, dict[str, Any]]: ...

def write_image(image: numpy.typing.ArrayLike, path: Path) -> None:
    """PNG/JPEG 8-bit sRGB, EXR/HDR/TIFF float, by extension. Raises ValueError."""
def read_image(path: Path) -> FloatImage:
    """Linear RGB float32 (height, width, 3). Raises ValueError."""
def compare(image: numpy.typing.ArrayLike, reference: numpy.typing.ArrayLike) -> Comparison: ...
def field(count: int, seed: int = 1) -> Scene:
    """The field of `count` balls whitted-field writes."""
def turntable(scene: Scene, frames: int) -> list[Camera]:
    """The cameras of whitted-render --turntable frames; the first is the scene's."""
