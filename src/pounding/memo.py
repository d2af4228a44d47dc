"""A small bounded memo for what many runs in one process share.

A sweep runs thousands of cases that differ in a parameter or two: the buildings, their
modal analysis and system matrices, the record and its samples on the output grid are the
same from case to case. :class:`Memo` remembers such values, least recently used first out,
bounded in entries and in bytes, so a long sweep's memory stays flat.

A key must hold everything that determines the value. Values are shared, so only immutable
ones belong here (frozen dataclasses with read-only arrays). A key may name objects by
identity (``id``); their entry then keeps them alive (``keep``), so that no other object can
take their ``id`` while the entry lasts.
"""

from __future__ import annotations

import threading
from collections import OrderedDict
from collections.abc import Callable, Hashable
from typing import Any, TypeVar

__all__ = ["Memo"]

T = TypeVar("T")


class Memo:
    """Remember values by key, at most ``max_items`` of them and ``max_bytes`` in all.

    Parameters
    ----------
    max_items : int
        Most entries kept; the least recently used goes first.
    max_bytes : int
        Most bytes kept, as the ``size`` of :meth:`get` counts them (a value larger than
        this alone is returned but not kept).

    Examples
    --------
    >>> memo = Memo(max_items=2)
    >>> memo.get(("a", 1), lambda: [1, 2])
    [1, 2]
    >>> len(memo)
    1
    """

    def __init__(self, max_items: int, max_bytes: int = 1 << 62) -> None:
        self.max_items = max_items
        self.max_bytes = max_bytes
        self._entries: OrderedDict[Hashable, tuple[Any, int, Any]] = OrderedDict()
        self._bytes = 0
        self._lock = threading.Lock()

    def get(self, key: Hashable, make: Callable[[], T], size: Callable[[T], int] | None = None,
            keep: Any = None) -> T:
        """The value of ``key``: remembered, or made now by ``make()`` and remembered.

        Parameters
        ----------
        key : hashable
            Everything that determines the value.
        make : callable
            Makes the value (an exception propagates, and nothing is remembered).
        size : callable, optional
            Bytes the value holds (default 0: counted by ``max_items`` only).
        keep : object, optional
            Kept alive with the entry: the objects a key names by ``id``.

        Returns
        -------
        The value.
        """
        with self._lock:
            entry = self._entries.get(key)
            if entry is not None:
                self._entries.move_to_end(key)
                return entry[0]
        value = make()
        nbytes = size(value) if size is not None else 0
        if nbytes > self.max_bytes:
            return value
        with self._lock:
            old = self._entries.pop(key, None)
            if old is not None:
                self._bytes -= old[1]
            self._entries[key] = (value, nbytes, keep)
            self._bytes += nbytes
            while len(self._entries) > self.max_items or self._bytes > self.max_bytes:
                _, (_, dropped, _) = self._entries.popitem(last=False)
                self._bytes -= dropped
        return value

    def find(self, key: Hashable) -> Any:
        """The value of ``key`` if it is remembered (it becomes the most recently used),
        else None. Nothing is made."""
        with self._lock:
            entry = self._entries.get(key)
            if entry is None:
                return None
            self._entries.move_to_end(key)
            return entry[0]

    def __len__(self) -> int:
        return len(self._entries)

    @property
    def nbytes(self) -> int:
        """Bytes held, as counted by the ``size`` of :meth:`get`."""
        return self._bytes

    def clear(self) -> None:
        """Forget every entry."""
        with self._lock:
            self._entries.clear()
            self._bytes = 0
