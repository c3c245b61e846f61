"""Extraordinary vertices of surface subdivision schemes: the local subdivision matrix at a vertex of
valence n, its Fourier blocks, its certified eigen-structure (Reif's conditions) and the curvature
behaviour read from its eigenvalues.

:mod:`.rules` holds the rules as data (catalogue schemes and user stencils), :mod:`.blocks` the
discrete Fourier transform of the rotational symmetry (one small block per frequency k, exact in
cos(2 pi k/n)), :mod:`.spectrum` the certified spectrum and the checks. Layering: modules here import the
algebra layer (the reader) and the results contract only; the command line imports them.
"""
