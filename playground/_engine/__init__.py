"""The engine-access layer: every read and write below pymunk's public objects.

Chipmunk's C getters and callbacks (:mod:`~playground._engine.raw`), a controller's reads of its
body, its ground and the space (:mod:`~playground._engine.state`), the nearest-hit queries
(:mod:`~playground._engine.sweep`, :mod:`~playground._engine.reach`, sharing
:mod:`~playground._engine.query`), a body's contacts (:mod:`~playground._engine.contacts`) and
``pymunk.batch`` rows (:mod:`~playground._engine.batch`). Each fast path is checked bit for bit
against pymunk's public API in ``tests/_engine/``; nothing here imports playground but ``vec``.
"""
