"""The independent check behind ``verified: yes``.

A deliberate second implementation of the pressure angle (its own inversion and
its own search): it shares no formula with the solvers (:mod:`optimize`) nor
with the product's kinematics; the layer rule keeps it so.
"""
