"""The package's version: one place, read by setuptools (pyproject's dynamic version), the
command line's ``--version`` and the scene schema's ``$id``."""

__version__ = "0.1.0"
