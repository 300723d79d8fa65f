"""python3 -m dem.plots FIGURE ...: a figure from files, without a server.

    stress-settlement FILE PNG [--wall W ...]   from monitor.csv, walls.csv, compression.csv or a .mcap recording
"""

import sys

from .stress_settlement import main as stress_settlement

FIGURES = {"stress-settlement": stress_settlement}

if len(sys.argv) < 2 or sys.argv[1] not in FIGURES:
    sys.exit(__doc__.strip() + "\n")
FIGURES[sys.argv[1]](sys.argv[2:])
