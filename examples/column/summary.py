#!/usr/bin/python3
"""Kept for old commands: the per-phase table is `tools/nscd-analysis phases LOG...`
(doc/analysis.md); this forwards its arguments there."""
import os
import sys

tools = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
sys.path.insert(0, tools)
from nscd_analysis.cli import main  # noqa: E402

sys.exit(main(["phases"] + sys.argv[1:]))
