"""The motion of a scene's body in time: :func:`simulate` and :class:`Simulation`."""

from __future__ import annotations

from typing import Any, Optional, Sequence

from . import _native
from ._scene import SceneSource, read


class Simulation:
    """Samples of a body's motion, each a NumPy array with a row per sample time:

    - ``t`` (s);
    - ``omega``, the angular velocity in body axes (rad/s), shape ``(n, 3)``;
    - ``orientation``, the unit quaternion ``(w, x, y, z)`` taking body axes to fixed
      axes, shape ``(n, 4)``;
    - ``T``, the kinetic energy of rotation ½{ω}ᵀ[I]{ω} (J);
    - ``H``, the magnitude of the angular momentum about G, |[I]{ω}| (kg·m²/s);

    and ``method``: ``exact`` (the closed form of torque-free motion) or ``integrated``.
    """

    def __init__(self, columns: dict) -> None:
        import numpy as np

        self.t: Any = np.asarray(columns["t"], dtype=float)
        self.omega: Any = np.asarray(columns["omega"], dtype=float).reshape(-1, 3)
        self.orientation: Any = np.asarray(columns["orientation"], dtype=float).reshape(-1, 4)
        self.T: Any = np.asarray(columns["T"], dtype=float)
        self.H: Any = np.asarray(columns["H"], dtype=float)
        self.method: str = columns["method"]

    def __len__(self) -> int:
        return len(self.t)

    def __repr__(self) -> str:
        span = f"t = {self.t[0]:g} … {self.t[-1]:g} s" if len(self.t) else "no samples"
        return f"<Simulation {len(self.t)} samples, {span}, {self.method}>"


def simulate(
    scene: SceneSource,
    until: Optional[float] = None,
    every: Optional[float] = None,
    at: Optional[Sequence[float]] = None,
    method: str = "auto",
    rtol: Optional[float] = None,
    step: Optional[float] = None,
) -> Simulation:
    """Integrates Euler's equations and the orientation for a scene's body (or heavy top)
    from t = 0, as ``kinetics simulate``.

    Samples every ``every`` seconds (default ``until/100``) up to ``until``, or at the
    times ``at``. ``method``: ``auto`` (the closed form when torque-free, else dop853, or
    vern9 below ``rtol`` 1e-9), ``exact``, ``dop853`` or ``vern9`` (with ``rtol``, default
    1e-10), ``rk4`` or ``splitting`` (with ``step``, default 1e-3 s).

    >>> import kinetics
    >>> run = kinetics.simulate("examples/scenes/spun_up_sphere.scene", until=1.0)
    >>> run.omega.shape, run.method
    ((101, 3), 'integrated')
    >>> run.omega[0].tolist()
    [1.0, 0.5, 0.0]
    """
    name, text = read(scene)
    times = None if at is None else [float(t) for t in at]
    return Simulation(_native.simulate(name, text, until, every, times, method, rtol, step))
