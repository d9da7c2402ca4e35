"""Motion laws and cycle programs (the first stage of the pipeline)."""

from laws.base import Law
from laws.characteristics import Characteristics, characteristics, law_table
from laws.diagnostics import Impact, LawJump, find_impacts, law_jumps
from laws.errors import CamsError, InfeasibleError, InputError
from laws.modified import ModifiedCycloid, ModifiedSine, ModifiedTrapezoid
from laws.polynomial import PolynomialLaw
from laws.program import Motion, Phase, Program
from laws.registry import LAWS, get_law
from laws.spline import SplineLaw
from laws.table import TableLaw

__all__ = [
    "Law",
    "LAWS",
    "get_law",
    "Phase",
    "Program",
    "Motion",
    "CamsError",
    "InputError",
    "InfeasibleError",
    "ModifiedTrapezoid",
    "ModifiedSine",
    "ModifiedCycloid",
    "PolynomialLaw",
    "TableLaw",
    "SplineLaw",
    "Characteristics",
    "characteristics",
    "law_table",
    "LawJump",
    "Impact",
    "law_jumps",
    "find_impacts",
]
