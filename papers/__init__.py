"""The bundled papers: one folder per paper (``papers/seed003/``) with its claims, the
transcriptions and derivations they need, its few bespoke evaluators and its golden verdicts
(``verdicts.json``, package data, what ``subdiv check`` compares with).

A paper folder's ``__init__.py`` defines ``PAPER`` (:class:`analysis.claims.Paper`);
:func:`analysis.claims.papers` finds every such folder. Layering: a paper may import the whole
engine (``analysis``, except :mod:`analysis.cli`) and the catalogue (``schemes``).
"""

from pathlib import Path


def load_bundled(init_file: str):
    """The ``PAPER`` of a bundled paper folder: its ``paper.toml`` (beside ``init_file``), with
    schemes given by catalogue name resolved in :mod:`schemes` (the engine may not import the
    catalogue, so the paper supplies the lookup). Its ``python`` claims run: the evaluators of a
    bundled paper are the tool's own code (a paper file from elsewhere runs none without
    ``--allow-python``)."""
    from analysis.claims.paperfile import load_paper

    paper = load_paper(Path(init_file).with_name("paper.toml"), catalogue=catalogue, python="bundled")
    # the folder's package (so that golden_path finds verdicts.json without papers() having run)
    object.__setattr__(paper, "origin", f"{__name__}.{Path(init_file).parent.name}")
    return paper


def catalogue(name: str):
    """A catalogue entry by slug: a stationary scheme (:func:`schemes.get`) or, failing that, a
    level-dependent one (:func:`schemes.level_dependent.get`)."""
    import schemes
    import schemes.level_dependent as ld
    from analysis.result import AnalysisError

    try:
        return schemes.get(name)
    except AnalysisError:
        if name in ld.names():
            return ld.get(name)
        raise
