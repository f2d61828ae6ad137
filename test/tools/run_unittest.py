#!/usr/bin/env python3
"""Runs one unittest module of test/tools for ctest. Exit 77 (ctest: skipped)
when pyserial is missing (robotctl tests) or when every test of the module was skipped, with
the reasons printed; 1 on any failure."""
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools", "robotctl"))
sys.path.insert(0, HERE)

if sys.argv[1].startswith("test_robotctl"):
    try:
        import serial  # noqa: F401
    except ImportError:
        print("SKIP: pyserial is not installed (tools/dev python_env installs it)")
        sys.exit(77)

suite = unittest.defaultTestLoader.loadTestsFromName(sys.argv[1])
result = unittest.TextTestRunner(verbosity=2).run(suite)
if not result.wasSuccessful():
    sys.exit(1)
if result.skipped and len(result.skipped) >= result.testsRun:
    for _, reason in result.skipped[:1]:
        print(f"SKIP: {reason}")
    sys.exit(77)
sys.exit(0)
