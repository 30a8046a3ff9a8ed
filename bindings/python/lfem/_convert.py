"""Argument checks of the bindings, done before anything reaches lfem: a value of the wrong type
raises TypeError, one of the wrong length or shape InvalidArgumentError (a ValueError), each
naming the argument. ctypes alone would pass a short tuple on zero-filled, or leak its own
ArgumentError."""

from __future__ import annotations

import numbers
import os
from typing import Any, Optional

import numpy as np
import numpy.typing as npt

from ._errors import InvalidArgumentError

_U32_MAX = 0xFFFFFFFF


def _kind(value: Any) -> str:
    return type(value).__name__


def real(value: Any, name: str) -> float:
    """A real number (int, float, numpy scalar; not bool, not str)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise TypeError("lfem: %s must be a real number, not %s" % (name, _kind(value)))
    return float(value)


def count(value: Any, name: str) -> int:
    """An integer in [0, 2^32) (a count or an index, C's uint32_t)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise TypeError("lfem: %s must be an integer, not %s" % (name, _kind(value)))
    if not 0 <= int(value) <= _U32_MAX:
        raise InvalidArgumentError("lfem: %s = %d is outside [0, 2^32)" % (name, value))
    return int(value)


def flag(value: Any, name: str) -> int:
    """A bool (or 0 / 1), as C's uint8_t flag."""
    if isinstance(value, (bool, np.bool_)) or (isinstance(value, numbers.Integral)
                                                and int(value) in (0, 1)):
        return int(bool(value))
    raise TypeError("lfem: %s must be a bool, not %s" % (name, _kind(value)))


def _real_array(value: Any, name: str, what: str) -> np.ndarray:
    try:
        a = np.asarray(value)
    except (TypeError, ValueError) as e:  # ragged nesting
        raise TypeError("lfem: %s must be %s: %s" % (name, what, e)) from None
    if a.dtype.kind not in "iuf":
        raise TypeError("lfem: %s must be %s, not %s of %s" % (name, what, _kind(value), a.dtype))
    return np.ascontiguousarray(a, dtype=np.float64)


def vector(value: npt.ArrayLike, name: str, length: int = 3) -> np.ndarray:
    """A float64 array of exactly `length` real numbers (a short one is refused, not padded)."""
    a = _real_array(value, name, "%d real numbers" % length)
    if a.shape != (length,):
        raise InvalidArgumentError("lfem: %s must have %d components, got shape %s"
                                   % (name, length, a.shape))
    return a


def vectors(values: npt.ArrayLike, name: str, rows: Optional[int] = None) -> np.ndarray:
    """A C-contiguous float64 (n, 3) array (a flat array of 3n numbers is accepted)."""
    a = _real_array(values, name, "an (n, 3) array of real numbers")
    if a.ndim == 1 and a.size % 3 == 0:
        a = a.reshape(-1, 3)
    if a.ndim != 2 or a.shape[1] != 3 or (rows is not None and a.shape[0] != rows):
        expected = "(%d, 3)" % rows if rows is not None else "(n, 3)"
        raise InvalidArgumentError("lfem: %s must be an %s array, got shape %s"
                                   % (name, expected, a.shape))
    return a


def indices(values: npt.ArrayLike, name: str) -> np.ndarray:
    """A flat C-contiguous uint32 array of integers in [0, 2^32)."""
    try:
        a = np.asarray(values)
    except (TypeError, ValueError) as e:
        raise TypeError("lfem: %s must be integers: %s" % (name, e)) from None
    if a.dtype.kind not in "iu" and not (a.size == 0 and a.dtype.kind == "f"):
        raise TypeError("lfem: %s must be integers, not %s of %s" % (name, _kind(values), a.dtype))
    a = a.reshape(-1)
    if a.size and (int(a.min()) < 0 or int(a.max()) > _U32_MAX):
        raise InvalidArgumentError("lfem: %s holds an index outside [0, 2^32)" % name)
    return np.ascontiguousarray(a, dtype=np.uint32)


def out_buffer(out: Any, name: str) -> np.ndarray:
    """A caller's buffer that lfem writes into directly: a writeable C-contiguous float64
    (k, 3) array."""
    if not isinstance(out, np.ndarray):
        raise TypeError("lfem: %s must be a numpy array, not %s" % (name, _kind(out)))
    if (out.dtype != np.float64 or out.ndim != 2 or out.shape[1] != 3
            or not out.flags.c_contiguous or not out.flags.writeable):
        raise InvalidArgumentError("lfem: %s must be a writeable C-contiguous float64 (n, 3) "
                                   "array, got %s %s" % (name, out.dtype, out.shape))
    return out


def path(value: Any, name: str) -> bytes:
    """A file system path (str, bytes or os.PathLike) as bytes for C."""
    try:
        return os.fsencode(value)
    except TypeError:
        raise TypeError("lfem: %s must be a path, not %s" % (name, _kind(value))) from None
