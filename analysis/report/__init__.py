"""Rendering only: Markdown and HTML proof-check reports (:mod:`.render`) and figures (:mod:`.plots`).

Nothing here computes a result; it draws and writes what the engine returned. Layering: may
import :mod:`analysis.claims` and the engine layers' result types, never :mod:`analysis.cli`.
"""
