"""Scenes as the compiled module takes them: JSON text."""
import json
import os

from . import _grainlab
from ._errors import SceneError


def presets():
    """The preset names, in the order `grainlab presets` lists them."""
    return list(_grainlab.presets())


def preset(name):
    """A preset as a scene dict (a starting point to edit). Raises SceneError for an unknown name."""
    return json.loads(_grainlab.preset_json(name))


def scene_text(scene):
    """JSON text for a scene dict, a preset name, a path to a scene file or JSON text."""
    if isinstance(scene, dict):
        try:
            return json.dumps(scene, allow_nan=False)
        except (TypeError, ValueError) as e:
            raise SceneError("(json)", f"the scene cannot be written as JSON: {e}") from None
    if isinstance(scene, os.PathLike):
        with open(scene) as f:
            return f.read()
    if isinstance(scene, str):
        if scene.lstrip().startswith("{"):
            return scene
        if scene in _grainlab.presets():
            return _grainlab.preset_json(scene)
        if os.path.isfile(scene):
            with open(scene) as f:
                return f.read()
        raise SceneError("preset", f"no preset or scene file named {scene!r}")
    raise TypeError(f"expected a scene dict, a preset name or a path, got {type(scene).__name__}")


def validate(scene):
    """Parses and checks a scene (dict, preset name or path) as `grainlab run` does. Returns None;
    raises SceneError with .field (a JSON path such as "material.friction") and .reason."""
    _grainlab.validate_json(scene_text(scene))
