"""Code separation checks: the separation a seismic code asks for between neighbouring
buildings, from the code's own procedure on the model's buildings, beside the model's gaps,
floor by floor, each number with its clause (``docs/codes.md``).

One module a code: :mod:`~pounding.studies.codes.asce7_22` (ASCE/SEI 7-22 §12.12) and
:mod:`~pounding.studies.codes.en1998_1` (EN 1998-1:2004 §4.4.2.7 with §4.3.4); what they
share (the modal response spectrum analysis at a contact point, the result table) is in
:mod:`~pounding.studies.codes.common`. :func:`code_check` picks the code by its key.
"""

from __future__ import annotations

from typing import Any

from pounding.studies.codes.common import COMBINATIONS, CodeCheck, CodeCheckRow

__all__ = ["CODES", "CODE_CHECK_FILE", "COMBINATIONS", "CodeCheck", "CodeCheckRow", "code_check",
           "write_code_check"]

CODES: dict[str, str] = {
    "asce7-22": "ASCE/SEI 7-22 §12.12 (δ_M = C_d δ_max / I_e, SRSS on one property)",
    "en1998-1": "EN 1998-1:2004 §4.4.2.7 with §4.3.4 (d_s = q_d d_e, SRSS, 0.7 at equal "
                "floors)",
}
"""The codes checked, by key."""


def code_check(model: Any, code: str, **parameters: Any) -> CodeCheck:
    """The separation check of ``code`` on a :class:`~pounding.model.PoundingModel`.

    Parameters
    ----------
    model : PoundingModel
    code : {"asce7-22", "en1998-1"}
    **parameters
        The code's inputs: :class:`~pounding.studies.codes.asce7_22.Asce722Parameters`
        or :class:`~pounding.studies.codes.en1998_1.En19981Parameters`.

    Raises
    ------
    ValueError
        An unknown code, a missing or bad parameter, a model the check does not cover: one
        line naming the field and the value.
    """
    import dataclasses
    import importlib

    if code in CODES:  # one module a code: asce7_22, en1998_1
        module: Any = importlib.import_module(
            f"pounding.studies.codes.{code.replace('-', '_').replace('.', '_')}")
        kind: Any = module.PARAMETERS
    else:
        raise ValueError(f"code: must be one of {', '.join(CODES)} (got {code!r})")
    fields = {f.name: f for f in dataclasses.fields(kind)}
    unknown = [k for k in parameters if k not in fields]
    if unknown:
        raise ValueError(f"{unknown[0]}: not a parameter of {code} (its parameters: "
                         f"{', '.join(fields)})")
    for name, f in fields.items():
        needed = (f.default is dataclasses.MISSING
                  and f.default_factory is dataclasses.MISSING)
        if needed and parameters.get(name) is None:
            raise ValueError(f"{name}: {code} needs it (got none)")
    given = {k: v for k, v in parameters.items() if v is not None}
    return module.check(model, kind(**given))


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
