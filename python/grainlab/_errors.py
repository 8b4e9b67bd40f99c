"""The exceptions of the grainlab package (the compiled half raises them too)."""


class SceneError(ValueError):
    """A scene that cannot be run. ``field`` is the JSON path of the offending value
    (``"material.friction"``, ``"particles[3].radius"``), ``reason`` says what is wrong."""

    def __init__(self, field, reason):
        super().__init__(f"{field}: {reason}")
        self.field = field
        self.reason = reason
