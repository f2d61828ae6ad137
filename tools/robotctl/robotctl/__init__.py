"""robotctl: a command line client for Strider robots (docs/robotctl.md)."""
__version__ = "0.1.0"
