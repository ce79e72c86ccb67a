#!/usr/bin/env python3
"""Draws the figures of a signorini run from its output folder: the command; the work is in
signorini_figures.py beside it (see there and docs/output.md).

    python3 tools/plot_results.py OUTDIR [--scale S] [--quiet]
    python3 tools/plot_results.py --check

A script run as a command is compiled on every run, a module that it imports is not: Python takes
signorini_figures from its __pycache__ when the build or the installation has compiled it (a
fortieth of a second of the figures' second).
"""

import signorini_figures  # the script's folder is the first place Python looks

signorini_figures.run()
