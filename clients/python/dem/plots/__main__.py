"""python3 -m dem.plots FIGURE ...: a figure from files, without a server.

    stress-settlement FILE PNG [--wall W ...]   from monitor.csv, walls.csv, compression.csv or a .mcap recording
    randall DIR [OUT]                           Randall's chapter 6 figures from a dem_validate randall-* or hopper directory
                                                (randall-centripetal: Figs. 6.4-6.8)
    miyata RUN_DIR [OUT_DIR]                    Miyata et al.'s Figs. 26-37 from a run with output.compression
"""

import sys

from .randall import main as randall
from .miyata import main as miyata
from .stress_settlement import main as stress_settlement

FIGURES = {"stress-settlement": stress_settlement, "randall": randall, "miyata": miyata}

if len(sys.argv) < 2 or sys.argv[1] not in FIGURES:
    sys.exit(__doc__.strip() + "\n")
FIGURES[sys.argv[1]](sys.argv[2:])
