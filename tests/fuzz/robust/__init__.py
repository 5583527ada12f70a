"""Robustness fuzzing: mutated and random input for every spinemu command, looking for crashes.

``python -m tests.fuzz.robust --seed N --cases C`` runs a campaign; see
:mod:`.cases` for what is generated, :mod:`.campaign` for what counts as a
finding, and docs/robustness.md for how to reproduce a failing seed.
"""
