"""The World's own error: a method called where it cannot act.

Bad values are ``ValueError`` naming the argument; this is for a call at the wrong moment — a
step from inside a step, sleeping a body that is not in the space yet — which no argument could
make right.
"""

from __future__ import annotations

__all__ = ["WorldUsageError"]


class WorldUsageError(RuntimeError):
    """A World method called where it cannot act; the message says what to do instead."""
