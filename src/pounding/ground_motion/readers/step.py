"""The time step of a record file: stated in the file, given by the caller, or both, in
which case they must agree (:func:`resolve_dt`)."""

from __future__ import annotations

from pounding.validation import positive

__all__ = ["DT_RTOL", "resolve_dt"]

DT_RTOL = 1e-6
"""How closely [relative] a ``dt`` given by the caller must agree with the file's."""


def resolve_dt(stated: float | None, given: float | None, where: str, *, stated_at: str,
               missing: str) -> float:
    """The time step [s] to read a file with.

    Parameters
    ----------
    stated : float or None
        The step the file states [s], already checked > 0.
    given : float or None
        The step the caller gives [s], for a file that states none.
    where : str
        The file, for the messages.
    stated_at : str
        Where and under what name the file states it, e.g. ``"line 4: DT"``.
    missing : str
        The message (after the file name) for a file that states none and is given none.

    Raises
    ------
    ValueError
        If the file states none and none is given, if ``given`` is not a positive number, or
        if the two differ by more than :data:`DT_RTOL` relative.
    """
    if stated is None:
        if given is None:
            raise ValueError(f"{where}: {missing}")
        return positive("dt [s]", given)
    if given is not None:
        step = positive("dt [s]", given)
        if abs(step - stated) > DT_RTOL * stated:
            raise ValueError(f"{where}: {stated_at} = {stated:g} s in the file but dt = "
                             f"{step:g} s was given")
    return stated
