"""python3 -m dem.plots FIGURE ...: a figure from files, without a server.

    stress-settlement MONITOR_CSV PNG [--wall W ...]   a demctl monitor recording
"""

import sys

from .stress_settlement import main as stress_settlement

FIGURES = {"stress-settlement": stress_settlement}

if len(sys.argv) < 2 or sys.argv[1] not in FIGURES:
    sys.exit(__doc__.strip() + "\n")
FIGURES[sys.argv[1]](sys.argv[2:])
