"""The bundled papers: one folder per paper (``papers/seed003/``) with its claims, the
transcriptions and derivations they need, its few bespoke evaluators and its golden verdicts
(``verdicts.json``, package data, what ``subdiv check`` compares with).

A paper folder's ``__init__.py`` defines ``PAPER`` (:class:`analysis.claims.Paper`);
:func:`analysis.claims.papers` finds every such folder. Layering: a paper may import the whole
engine (``analysis``, except :mod:`analysis.cli`) and the catalogue (``schemes``).
"""
