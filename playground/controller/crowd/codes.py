"""A member's state in a crowd's arrays, as a code (``np.int8``): 0 runs its own step (any
state but the two common ones, or one of them with more pending), 1 GROUNDED, 2 AIRBORNE."""

from __future__ import annotations

import numpy as np

from playground.controller.states import AIRBORNE, GROUNDED

__all__ = ["AIRBORNE_CODE", "CODES", "GROUNDED_CODE", "STATES"]

CODES = {GROUNDED: 1, AIRBORNE: 2}
STATES = (None, GROUNDED, AIRBORNE)
GROUNDED_CODE, AIRBORNE_CODE = np.int8(CODES[GROUNDED]), np.int8(CODES[AIRBORNE])
