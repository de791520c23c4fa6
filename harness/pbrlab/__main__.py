"""``python -m pbrlab``: the ``pbrlab`` command (pbrlab.commands.cli)."""

import sys

from .commands.cli import main

sys.exit(main())
