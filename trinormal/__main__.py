"""``python -m trinormal A B C``: the command line calculator."""

import sys

from trinormal.cli import main

sys.exit(main())
