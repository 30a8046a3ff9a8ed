"""The exceptions of the bindings: every failed lfem call raises LfemError."""

from __future__ import annotations

import enum


class Status(enum.IntEnum):
    """lfem_status without LFEM_OK's meaning of success (Status.OK is 0)."""

    OK = 0
    INVALID_ARGUMENT = 1  # a null pointer, a NaN, a number out of its range
    INVALID_MESH = 2      # bad indices, inverted or zero-volume tets, unused nodes
    INVALID_HANDLE = 3    # a stale, foreign or null body handle
    BUFFER_TOO_SMALL = 4  # the caller's capacity is below what the answer needs
    UNSTABLE = 5          # the state blew up; the world was rolled back
    IO_ERROR = 6          # a file could not be read or written, or is malformed
    OUT_OF_MEMORY = 7
    INTERNAL_ERROR = 8    # a bug in lfem: please report it with the message
    UNSUPPORTED = 9       # this build leaves the feature out (LFEM_WITH_CCD, LFEM_WITH_IO)


class LfemError(Exception):
    """A failed lfem call: .status (a Status, or the raw int of a status this version does not
    know) and .message (lfem_last_error, or the bindings' own message)."""

    def __init__(self, status: Status | int, message: str) -> None:
        try:
            status = Status(status)
        except ValueError:
            pass
        super().__init__(message)
        self.status = status
        self.message = message

    def __str__(self) -> str:
        name = self.status.name if isinstance(self.status, Status) else str(self.status)
        return "%s (%s)" % (self.message, name)


class InvalidArgumentError(LfemError, ValueError):
    """Status.INVALID_ARGUMENT: a value refused, by lfem or by these bindings (a vector of the
    wrong length, an array of the wrong shape). Also a ValueError, as Python code expects."""

    def __init__(self, message: str, status: Status | int = Status.INVALID_ARGUMENT) -> None:
        super().__init__(status, message)


def error(status: int, message: str) -> LfemError:
    """The exception for a failed call: InvalidArgumentError for INVALID_ARGUMENT."""
    if status == Status.INVALID_ARGUMENT:
        return InvalidArgumentError(message)
    return LfemError(status, message)


def renamed(e: LfemError, inner: str, outer: str) -> LfemError:
    """The same error naming the call the user made (outer, e.g. lfem_body_get_positions) in
    place of the helper call that failed first inside it (inner, lfem_body_get_node_count)."""
    message = e.message
    if message.startswith(inner + ":"):
        message = outer + message[len(inner):]
    return error(e.status, message)
