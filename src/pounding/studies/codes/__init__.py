"""Code separation checks: the separation a seismic code asks for between neighbouring
buildings, from the code's own procedure on the model's buildings, beside the model's gaps,
floor by floor, each number with its clause (``docs/codes.md``).

One module a code: :mod:`~pounding.studies.codes.asce7_22` (ASCE/SEI 7-22 §12.12, its
equivalent lateral force procedure in :mod:`~pounding.studies.codes.asce7_22_elf`),
:mod:`~pounding.studies.codes.en1998_1` (EN 1998-1:2004 §4.4.2.7 with §4.3.4),
:mod:`~pounding.studies.codes.nzs1170_5` (NZS 1170.5:2004 §7.4),
:mod:`~pounding.studies.codes.nbcc2020` (NBCC 2020 Sentence 4.1.8.14) and
:mod:`~pounding.studies.codes.is1893` (IS 1893 (Part 1):2016 §7.11.3); what they share (the
modal response spectrum analysis at a contact point, the parameter checks, the rows, the
result table) is in :mod:`~pounding.studies.codes.common`. :func:`code_check` picks the
code by its key.
"""

from __future__ import annotations

from typing import Any

from pounding.studies.codes.common import COMBINATIONS, CodeCheck, CodeCheckRow

__all__ = ["CODES", "CODE_CHECK_FILE", "COMBINATIONS", "CodeCheck", "CodeCheckRow", "code_check",
           "code_parameters", "write_code_check"]

CODES: dict[str, str] = {
    "asce7-22": "ASCE/SEI 7-22 §12.12 (δ_M = C_d δ_max / I_e, SRSS on one property)",
    "en1998-1": "EN 1998-1:2004 §4.4.2.7 with §4.3.4 (d_s = q_d d_e, SRSS, 0.7 at equal "
                "floors)",
    "nzs1170.5": "NZS 1170.5:2004 §7.4 with §7.2 (design deflections (μ/k_μ) d_e, SRSS on "
                 "one site)",
    "nbcc2020": "NBCC 2020 Sentence 4.1.8.14 with 4.1.8.13 (deflections × R_d R_o/I_E, "
                "SRSS)",
    "is1893": "IS 1893 (Part 1):2016 §7.11.3 (R (Δ1 + Δ2), R/2 at equal floors)",
}
"""The codes checked, by key."""


def _module(code: str) -> Any:
    """The module of ``code`` (one a code: asce7_22, en1998_1, nzs1170_5, nbcc2020,
    is1893)."""
    import importlib

    if code not in CODES:
        raise ValueError(f"code: must be one of {', '.join(CODES)} (got {code!r})")
    return importlib.import_module(
        f"pounding.studies.codes.{code.replace('-', '_').replace('.', '_')}")


def code_parameters(code: str) -> dict[str, bool]:
    """The parameters of ``code``'s check, each with whether it must be given."""
    import dataclasses

    return {f.name: (f.default is dataclasses.MISSING
                     and f.default_factory is dataclasses.MISSING)
            for f in dataclasses.fields(_module(code).PARAMETERS)}


def code_check(model: Any, code: str, **parameters: Any) -> CodeCheck:
    """The separation check of ``code`` on a :class:`~pounding.model.PoundingModel`.

    Parameters
    ----------
    model : PoundingModel
    code : {"asce7-22", "en1998-1", "nzs1170.5", "nbcc2020", "is1893"}
    **parameters
        The code's inputs: the fields of its module's ``PARAMETERS``
        (:class:`~pounding.studies.codes.asce7_22.Asce722Parameters`,
        :class:`~pounding.studies.codes.en1998_1.En19981Parameters`,
        :class:`~pounding.studies.codes.nzs1170_5.Nzs11705Parameters`,
        :class:`~pounding.studies.codes.nbcc2020.Nbcc2020Parameters`,
        :class:`~pounding.studies.codes.is1893.Is1893Parameters`).

    Raises
    ------
    ValueError
        An unknown code, a missing or bad parameter, a model the check does not cover: one
        line naming the field and the value.
    """
    module = _module(code)
    fields = code_parameters(code)
    unknown = [k for k in parameters if k not in fields]
    if unknown:
        raise ValueError(f"{unknown[0]}: not a parameter of {code} (its parameters: "
                         f"{', '.join(fields)})")
    for name, needed in fields.items():
        if needed and parameters.get(name) is None:
            raise ValueError(f"{name}: {code} needs it (got none)")
    given = {k: v for k, v in parameters.items() if v is not None}
    import numpy as np

    # absurd spectra overflow: the checks refuse every displacement that is not a finite
    # number in one line (common.modal_point_peak, separation_rows), so NumPy's own
    # warnings would only be noise around that line
    with np.errstate(over="ignore", invalid="ignore"):
        return module.check(model, module.PARAMETERS(**given))


CODE_CHECK_FILE = "code_check.json"
"""The file ``pounding code-check --out DIR`` writes in ``DIR``."""


def write_code_check(check: CodeCheck, out: Any, overwrite: bool = False,
                     source: str = "") -> Any:
    """Write ``check`` as ``out/code_check.json`` (a new folder, or with ``overwrite`` one
    holding nothing but an earlier code check of pounding's: its manifest), built whole
    and then put in place. Returns the file's path.

    Raises
    ------
    ValueError
        ``out`` is a file, or exists without ``overwrite``, or holds anything pounding did
        not write; nothing is touched then.
    """
    import json
    from pathlib import Path

    from pounding.io.files import check_writable, write_text
    from pounding.io.manifest import check_out_folder
    from pounding.io.output_folder import new_output_folder, remove_stale

    folder = Path(out)
    if folder.name in ("", ".", ".."):
        raise ValueError(f"out: {out!s} is not a folder name; give e.g. --out results")
    check_writable(folder)
    remove_stale(folder.absolute().parent, restore=folder.absolute())
    check_out_folder(folder, overwrite, "code-check")
    data = {"model": source, **check.to_dict()} if source else check.to_dict()
    with new_output_folder(folder, "code-check", [CODE_CHECK_FILE],
                           check=lambda: check_out_folder(folder, overwrite, "code-check")
                           ) as tmp:
        write_text(tmp / CODE_CHECK_FILE, json.dumps(data, indent=2, ensure_ascii=False)
                   + "\n")
    return folder / CODE_CHECK_FILE
