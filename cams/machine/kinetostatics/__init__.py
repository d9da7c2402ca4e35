"""Kinetostatics of the seeds' linkages: reactions in every pair and the balancing moment over the cycle.

The package, by stage: :mod:`~cams.machine.kinetostatics.loads` (the inputs: masses, loads, friction),
:mod:`~cams.machine.kinetostatics.model` (bodies, pairs and loads from each machine's own topology),
:mod:`~cams.machine.kinetostatics.solve` (the linear solve, friction passes),
:mod:`~cams.machine.kinetostatics.result` (reactions, virtual work, reduced quantities) and
:mod:`~cams.machine.kinetostatics.coupling` (the machine with its flywheel and its cam). The machine
file's ``[forces]`` table is read by :mod:`cams.machine.machinefile`; the pictures are in
:mod:`cams.present.machine_plots`. This module re-exports the public names.

Method (seeds 000, 002, 004: "кинетостатика", d'Alembert)
---------------------------------------------------------
Every moving link is in equilibrium under its external loads, its weight,
its inertia force ``-m a_S`` at the centre of mass S and inertia moment
``-J_S epsilon``, and the reactions of the pairs it belongs to; the input
crank also carries the balancing moment ``M_b`` (уравновешивающий момент), the
moment the drive must apply for the crank to turn at its constant speed. For
a one-input linkage without redundant constraints the ``3 n`` equations
(n moving links) determine the ``2 p`` reaction components (p lower pairs)
and ``M_b``: one linear system per crank angle, solved for all angles at once
(``numpy.linalg.solve`` on a stack), instead of group by group as in the seeds'
force plans -- the unknowns are the same.

Pairs
-----
* revolute: the force ``R`` (complex ``Rx + i Ry``) on the pair's first link
  from its second, at the pair's centre;
* prismatic: the normal force ``N`` along ``n = i u`` (``u``: the guide's
  direction, fixed in the second link) at a reference point of the guide and
  a couple ``M`` (together: the normal force acting at ``M / N`` along ``u``
  from the reference point).

The second link gets the opposite force and couple. Ground is link 0.

Friction
--------
* constant loads, e.g. seal friction on a piston (seed 002's 60 N):
  :class:`ConstantFriction`;
* proportional to the reactions (seed 002's "two-stage method", seed 004's
  2.6): in a revolute pair a moment ``mu r |R|`` (journal radius ``r``)
  opposing the relative rotation, in a prismatic pair a force ``mu |N|``
  along the guide opposing the relative sliding. The first pass solves
  without them; each following pass applies the friction of the previous
  pass's reactions (``passes=2`` is the seeds' method; more passes iterate to
  the fixed point). The power lost in each pair is ``|M_f omega_rel|`` or
  ``|F_f v_rel|`` (seed 004, 2.6).

Virtual work (Zhukovsky's lever)
--------------------------------
The balancing moment also follows from the power of all loads, inertia and
friction included, without any reaction:
``M_b omega_1 = -sum(F . v + M omega)`` -- Zhukovsky's lever is the graphical
form of this sum (moments about the pole of the velocity plan turned by 90
degrees). :attr:`ForceResult.virtual_moment` computes it independently.

Reduced quantities (for :mod:`cams.machine.flywheel`)
---------------------------------------------
``J_red = sum(m |v_S|^2 + J_S omega^2) / omega_1^2`` and the reduced moment
of the external loads and weights ``Mr = -sum(F . v + M omega) / |omega_1|``
(positive resists), of friction ``Mf = (losses) / |omega_1|``.

Frames and units
----------------
The machine's frame (:mod:`cams.machine.linkage.machines`): origin at the crank centre,
angles counter-clockwise from +x; gravity acts along -y. Lengths are given in
the machine's unit and converted with ``length_unit`` (m per unit, 1e-3 for
mm); forces in N, moments in N m (counter-clockwise positive), masses in kg,
moments of inertia in kg m^2, the crank's speed from the machine's rpm.
"""

from cams.machine.kinetostatics.coupling import (
    CAM_ANGLE,
    CYCLE_ANGLE,
    MachineForces,
    machine_forces,
)
from cams.machine.kinetostatics.loads import (
    WINDOWS,
    ConstantFriction,
    ForceOptions,
    ForceSpec,
    Friction,
    G,
    GasPressure,
    LinkMass,
    Resistance,
    cycle_turns,
)
from cams.machine.kinetostatics.model import (
    GUIDED,
    JOINTS,
    LINKS,
    PINNED,
    AppliedLoad,
    Body,
    Joint,
    Model,
    build_model,
)
from cams.machine.kinetostatics.result import ForceResult
from cams.machine.kinetostatics.solve import analyse_forces, solve_model

__all__ = [
    "LinkMass",
    "Friction",
    "GasPressure",
    "Resistance",
    "ConstantFriction",
    "ForceSpec",
    "Body",
    "Joint",
    "AppliedLoad",
    "Model",
    "ForceResult",
    "build_model",
    "solve_model",
    "analyse_forces",
    "ForceOptions",
    "MachineForces",
    "machine_forces",
    "LINKS",
    "JOINTS",
    "WINDOWS",
    "PINNED",
    "cycle_turns",
    "GUIDED",
    "G",
    "CYCLE_ANGLE",
    "CAM_ANGLE",
]
