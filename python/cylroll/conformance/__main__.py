"""``python -m cylroll.conformance``: see :mod:`cylroll.conformance.cli`."""

import sys

from .cli import main

sys.exit(main())
