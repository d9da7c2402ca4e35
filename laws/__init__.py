"""Motion laws and cycle programs (the first stage of the pipeline)."""

from laws.base import Law
from laws.errors import CamsError, InfeasibleError, InputError
from laws.program import Motion, Phase, Program
from laws.registry import LAWS, get_law

__all__ = ["Law", "LAWS", "get_law", "Phase", "Program", "Motion", "CamsError", "InputError", "InfeasibleError"]
