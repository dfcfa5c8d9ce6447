"""The errors motostab raises (pure Python: the extension raises these classes)."""
from __future__ import annotations

from typing import Optional


class InputError(ValueError):
    """Bad input: a scenario, a measured-data file or an argument, located as precisely as known.

    ``str(error)`` is the command line's message (``file:line:col: key: reason``). The location:
    ``file`` (the file, or None for an argument), ``line`` and ``column`` (1-based, None if unknown),
    ``key`` (the dotted key path, e.g. ``rear_frame.mass_kg``, or the keyword argument) and
    ``reason`` (the message without the location).
    """

    def __init__(self, message: str, file: Optional[str] = None, line: Optional[int] = None,
                 column: Optional[int] = None, key: Optional[str] = None, reason: Optional[str] = None):
        super().__init__(message)
        self.file = file
        self.line = line
        self.column = column
        self.key = key
        self.reason = reason if reason is not None else message


class ResultError(RuntimeError):
    """Valid input, no result: a trim that did not converge, no hands-free turn, no mode identified.

    The command line exits with code 3 for these. ``result``, when not None, holds what was computed
    before the failure (e.g. a simulation's samples up to an integrator failure).
    """

    def __init__(self, message: str, result: object = None):
        super().__init__(message)
        self.result = result
