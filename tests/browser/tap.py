"""A tiny TAP producer: numbered checks, each "ok N - name" or "not ok N - name" with the reason as comments."""

from __future__ import annotations

import sys
import traceback
from typing import Callable, List, Optional, Tuple

Check = Tuple[str, Callable[[], None]]


class Failed(AssertionError):
    """A check's condition did not hold; its message says what was seen."""


def expect(condition: bool, message: str) -> None:
    if not condition:
        raise Failed(message)


def run(checks: List[Check], first: int = 1, cannot_run: Optional[str] = None) -> int:
    """Runs the checks in order and prints one TAP line each; returns how many failed.

    With `cannot_run` (why the checks cannot start, say no browser) every check is reported as
    failed with that reason, so a suite that cannot run still counts all its checks.
    """
    failed = 0
    for number, (name, body) in enumerate(checks, first):
        reason = cannot_run
        if reason is None:
            try:
                body()
            except Failed as error:
                reason = str(error)
            except Exception as error:  # a check that crashed fails with what crashed it
                reason = f"{type(error).__name__}: {error}\n" + traceback.format_exc(limit=3)
        if reason is None:
            print(f"ok {number} - {name}", flush=True)
        else:
            failed += 1
            print(f"not ok {number} - {name}", flush=True)
            for line in reason.rstrip().splitlines():
                print(f"#   {line}", flush=True)
    sys.stdout.flush()
    return failed
