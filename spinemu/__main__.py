"""``python -m spinemu`` is the same as the ``spinemu`` command."""
from .cli import entry_point

entry_point()
