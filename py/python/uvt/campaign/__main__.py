"""``python -m uvt.campaign``: see :mod:`uvt.campaign.cli`."""

import sys

from .cli import main

sys.exit(main())
