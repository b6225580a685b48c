"""``python -m trinormal.notebooks``: the same as the ``trinormal-notebooks`` command."""

import sys

from trinormal.notebooks import main

sys.exit(main())
