"""``python -m uvt.mutation``: see :mod:`uvt.mutation.cli`."""

import sys

from .cli import main

sys.exit(main())
