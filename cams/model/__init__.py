"""The problem, typed: followers, the design (motion program, limits, options).

The bottom layer of :mod:`cams`: it imports only :mod:`laws`.
"""
