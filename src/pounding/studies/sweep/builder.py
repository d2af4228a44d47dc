"""Building a case: the base model with the case's values, validated and built, sharing
what the cases of one sweep have in common.

The cases of a sweep differ in a parameter or two, and each part of a run depends on one
group of keys of the model file only: the model (buildings or a bridge, contacts and their
laws, devices, walls) on ``building``, ``bridge``, ``contact``, ``device``, ``wall`` and
``name``; the ground motion on ``record`` and ``spatial``; the solver
options on ``solver`` (``output`` and ``description`` change no run). A
:class:`CaseBuilder` remembers, for each group, what the cases it built made of it, keyed
by the case's values of that group's parameters: a case whose every group was seen in a
case that validated and built is put together from those parts, without validating or
building anything again (in a grid whose last parameter is the record's scale, each model
is built once, for the first of its scales). Any other case is validated and built whole,
exactly as ``pounding run`` does, so a case that fails reports the error it would alone.

Why a case put together from parts is the case: a group's part depends only on the keys of
that group (:func:`~pounding.studies.sweep.overrides.apply_overrides` changes keys within
the table of the path it sets), each group is validated apart from the others (the one
check across tables, ``contact.gaps`` against the buildings, lies in the model's group),
and a part is remembered only once a whole case with it validated and built. Values are
compared by ``repr``: equal text is equal data of the same types (``1`` and ``1.0``, ``0.0``
and ``-0.0`` differ, as they may in a run).
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from pounding.memo import Memo
from pounding.studies.sweep.overrides import _copy, apply_overrides

__all__ = ["CaseBuilder", "case_builder"]

_GROUPS: dict[str, str] = {"record": "record", "spatial": "record", "solver": "solver",
                           "output": "solver", "description": "solver"}
"""The group of each table of a model file (by the first key of a parameter path); every
other table (``building``, ``bridge``, ``contact``, ``device``, ``wall``, ``name``, and any
table added later) is in the group ``"model"``: a table not named here is taken to shape
the model, so a case of a new value is never put together from another's model. The
ground motion depends on ``record`` and on ``spatial`` (each building's motion made from
the record); the solver options on ``solver``, and ``output`` and ``description`` change
no run."""

MAX_PARTS = 256
"""Most parts a :class:`CaseBuilder` remembers per group."""

MAX_MODEL_BYTES = 64 << 20
"""Most bytes the models a :class:`CaseBuilder` remembers may hold. A model keeps its
kernel arrays (:func:`pounding.integrate.kernel_model`) while it lives, about ``64 N²``
bytes for N floors (:func:`_model_bytes`): hundreds of small models, a few of hundreds of
floors."""

MAX_RECORDS = 64
"""Most records (and their motions) a :class:`CaseBuilder` remembers, as
:data:`pounding.config.record.RECORDS`."""


def _model_bytes(model: Any) -> int:
    """Bytes a model holds with its kernel arrays, counted as
    :data:`pounding.integrate.kernel_model.STRUCTURES` counts them."""
    return 64 * int(model.n_dof) ** 2


class CaseBuilder:
    """The cases of one sweep, built: ``build(values)`` gives ``(model, motion, solver)``.

    Parameters
    ----------
    base : dict
        The base model configuration as plain data (copied: the builder keeps its own).
    base_dir : path-like
        Where relative paths of the base model start.
    params : sequence of str
        The swept parameters (dotted paths).
    max_parts : int
        Most parts remembered per group.
    """

    def __init__(self, base: dict[str, Any], base_dir: str | os.PathLike[str],
                 params: Sequence[str], max_parts: int = MAX_PARTS) -> None:
        self.base = _copy(base)
        self.base_dir = Path(base_dir)
        self.params = tuple(params)
        group = [_GROUPS.get(p.split(".")[0], "model") for p in self.params]
        self._columns = {g: tuple(i for i, x in enumerate(group) if x == g)
                         for g in ("model", "record", "solver")}
        self._parts = {"model": Memo(max_items=max_parts, max_bytes=MAX_MODEL_BYTES),
                       "record": Memo(max_items=min(max_parts, MAX_RECORDS)),
                       "solver": Memo(max_items=max_parts)}

    def _keys(self, values: Sequence[Any]) -> dict[str, str]:
        """Each group's key: the ``repr`` of the case's values of its parameters."""
        return {g: repr(tuple(values[i] for i in cols)) for g, cols in self._columns.items()}

    def build(self, values: Sequence[Any]) -> Any:
        """The case with these values (one per parameter), built.

        Returns
        -------
        pounding.config.run.Built
            ``(model, motion, solver_kwargs)``, as :meth:`pounding.config.RunConfig.build`.

        Raises
        ------
        pydantic.ValidationError, ValueError
            A value the model does not accept (as :meth:`RunConfig.model_validate
            <pounding.config.RunConfig>` and :meth:`~pounding.config.RunConfig.build`
            report it).
        """
        from pounding.config.base import prefixed
        from pounding.config.run import Built

        keys = self._keys(values)
        model, record, solver = (self._parts[g].find(keys[g])
                                 for g in ("model", "record", "solver"))
        if model is None or record is None or solver is None:
            from pounding.config import RunConfig

            data = apply_overrides(self.base, self.params, values)
            cfg = RunConfig.model_validate(data, context={"base_dir": self.base_dir})
            built = cfg.build()
            model = self._parts["model"].get(keys["model"], lambda: built.model,
                                             size=_model_bytes)
            # a record file may change: its motion is asked of the record each time
            # (RecordConfig.load, remembered by the file's version); a bundled one may not
            self._parts["record"].get(keys["record"], lambda: (
                cfg.record, cfg.spatial, built.motion if cfg.record.path is None else None))
            self._parts["solver"].get(keys["solver"], lambda: dict(built.solver))
            return Built(model, built.motion, built.solver)
        record_cfg, spatial_cfg, motion = record
        if motion is None:
            from pounding.structure.plan_row import PlanMatrixBuilding

            in_plan = any(isinstance(b, PlanMatrixBuilding) for b in model.buildings)
            with prefixed("record"):
                motion = record_cfg.load(components=in_plan)
            if spatial_cfg is not None:
                with prefixed("spatial"):
                    motion = spatial_cfg.apply(motion, record_cfg.factor_of(motion))
        return Built(model, motion, dict(solver))


_BUILDERS = Memo(max_items=4)
"""The builders of the sweeps run lately in this process, by their base, folder and
parameters."""


def case_builder(base: dict[str, Any], base_dir: str | os.PathLike[str],
                 params: Sequence[str]) -> CaseBuilder:
    """The :class:`CaseBuilder` of a sweep, the same one for every batch of it that runs in
    this process (remembered by the ``repr`` of its arguments)."""
    key = repr((base, str(base_dir), tuple(params)))
    return _BUILDERS.get(key, lambda: CaseBuilder(base, base_dir, params))
