"""The subcommands of ``cams``: one module each, with ``register(subparsers)``.

To add a command, write ``cams/commands/NAME.py`` with ``register`` and add
NAME to :data:`COMMANDS` (the order of ``cams --help``).
"""

COMMANDS = ("solve", "check", "profile", "plot", "report", "explore", "sweep", "machine", "new", "laws")
