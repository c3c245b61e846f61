"""A rigorous zero test for algebraic expressions (radicals, ``I``, ``CRootOf``), and their
certified Arb enclosures — the exact decisions behind masks typed in closed form
(:mod:`analysis.algebra.closed_form`).

Values and branches
-------------------
An expression is built from rationals, ``+ - * /``, integer powers and *atoms*: ``I``, principal
``k``-th roots ``b^(1/k)`` of sub-expressions ``b`` (``arg`` in ``(-pi/k, pi/k]``, as sympy
defines them) and ``CRootOf(f, j)`` (``f`` rational; the ball is flint's isolating ball that
meets sympy's isolating box). A root whose base lies on the branch cut (``b`` real ``< 0``) is
never evaluated from a ball that straddles the cut: ``b`` is first proven real by the zero test
(``b - conj(b) = 0``), then ``b^(1/k) = (-b)^(1/k) e^(i pi/k)``; a base proven non-real is
re-enclosed at higher precision until its ball leaves the axis.

Complex conjugates (reality proofs)
-----------------------------------
``conj`` of an expression is built structurally: ``I -> -I``; a sub-expression real *by
construction* (no ``I``, even roots of bases certified positive, real ``CRootOf``) is its own
conjugate; ``conj(CRootOf(f, j)) = CRootOf(f, j')`` with ``j'`` the unique index whose isolating
ball meets the conjugate of the ball of root ``j`` (``f`` is rational, so ``conj`` permutes its
roots; flint's isolating balls are disjoint, so one meeting is proof). The conjugate ``c`` of a
principal root ``r = b^(1/k)`` is rewritten in the atoms already present when that is *proven*:

* ``b`` proven real (``b - conj(b) = 0``): ``c = r`` if ``b > 0`` (ball); ``c = -r`` (``k = 2``)
  or ``c = -I r`` (``k = 4``) if ``b < 0`` (principal root ``|b|^(1/k) e^(i pi/k)``).
* another root atom ``r' = b'^(1/k)`` (no deeper than ``r``) with ``b' - conj(b) = 0`` proven:
  then ``c^k = conj(b) = r'^k`` and ``r' != 0``, so ``c / r'`` is a ``k``-th root of unity; it is
  the unique one whose ball meets the ball of ``c / r'`` (the true value lies in both), and it is
  used when it is ``+-1`` or ``+-I``.
* ``b conj(b) - R = 0`` proven for a rational ``R = rho^k``, ``rho > 0`` rational: then
  ``|r|^2 = |b|^(2/k) = rho`` and ``c = rho / r`` (Cardano's cube roots in the casus
  irreducibilis: ``|C|^2 = -p/3``).

Otherwise ``c`` stays a fresh atom (a ``k``-th root of ``conj(b)``). Every recursion these proofs
start (enclosures on the branch cut, conjugates of inner roots, partners no deeper than the root)
goes to strictly smaller root depth, so it terminates.

Zero test
---------
:meth:`_Algebra.zero` decides ``x = 0`` by the first of these that applies; each is a proof.

1. **Arb ball excluding 0** (64 and 256 bits): ``x != 0``.
2. **Formal identity.** Replace the atoms ``t_1..t_m`` by indeterminates and compute ``x`` as a
   quotient ``n/d`` of integer polynomials (fmpz_mpoly), by the same operations as the expression
   (an atom is one indeterminate wherever it occurs: equal atoms have equal values).
   Every divisor is certified nonzero at the true atom values (Arb ball excluding 0, else the zero
   test itself). By induction ``d(tau) != 0`` and ``x = n(tau)/d(tau)`` for the vector ``tau`` of
   atom values (evaluation is a ring homomorphism on the polynomials whose values are nonzero
   denominators). The numerator is reduced modulo the relations ``t^2 = -1`` (for ``I``) and
   ``c t^k = p`` for a root ``t`` whose base has the formal value ``p/c`` with a *constant* ``c``
   (``p`` in lower atoms; leading terms are pure powers of distinct variables, a Gröbner basis).
   All relations vanish at ``tau``; so a zero normal form proves ``x = 0``. (A nonzero normal form
   proves nothing: the test goes on.) This settles the identities of a Daubechies closed form,
   which hold in the roots ``z_k`` of the spectral factorisation, in milliseconds, whatever the
   degree of the field.
3. **Root separation** (Burnikel, Fleischer, Mehlhorn, Schirra). Write ``x = u / l`` with ``u``,
   ``l`` algebraic integers and track upper bounds ``U >= |sigma(u)|``, ``L >= |sigma(l)|`` over
   **all** embeddings ``sigma`` (``x + y: U = U_x L_y + U_y L_x, L = L_x L_y``; ``x y: U_x U_y,
   L_x L_y``; ``x / y: U_x L_y, L_x U_y``; ``x^(1/k): (U_x L_x^(k-1))^(1/k), L_x``; a root of
   ``c_n X^n + ...``: ``U = c_n (1 + max |c_i/c_n|)``, ``L = c_n``). If ``x`` lies in a field of
   degree ``<= D`` and ``u != 0``, its norm is a nonzero integer, so ``|u| >= U^-(D-1)`` and
   ``|x| >= 1 / (L U^(D-1))``: an Arb enclosure below that proves ``x = 0``.

   ``D`` (:func:`~analysis.algebra.expressions.degree_bound`) is a tower bound over the atoms of ``x`` *after* the rewriting
   of conjugates above, taken in an order where every base comes before its root: adjoining ``I``
   costs ``<= 2``, a ``k``-th root of an element of the field so far ``<= k`` (a conjugate root
   left as an atom is a ``k``-th root of the conjugate base, which is in the field so far; its
   ``U, L`` come from that base), the ``(j+1)``-th distinct root of a degree-``n`` polynomial
   ``f`` ``<= n - j`` (it is a root of ``f / prod(X - r_i)`` over the previous roots). The
   tightenings over a plain count of the atoms, each sound:

   * identical atoms are counted once (atoms are compared by structure: the same expression has
     the same value);
   * a conjugate of a sub-expression real by construction is that sub-expression, not an atom;
   * ``conj(CRootOf(f, j))`` is ``CRootOf(f, j')`` (above), so it counts among the ``<= n`` roots
     of the *same* ``f``: all roots of ``f`` together cost ``<= n!`` (the splitting field of a
     rational ``f`` has degree ``<= n!`` and is closed under conjugation);
   * a conjugate root rewritten above (``r``, ``-r``, ``-I r``, ``+-r'``, ``+-I r'``,
     ``rho / r``) is an expression in atoms already counted (plus ``I``, then counted): it is
     not an atom.

   For the benchmark's D8, D10, D12 closed forms this brings ``D`` from 18432, 1179648, 122880
   down to 192, 1536, 3840; root separation would still need ``4e5`` to ``2e8`` bits for them
   (``U`` is large), so it is the formal identity (step 2) that decides them. Root separation
   is the fallback (e.g. identities that need ``sqrt 2 sqrt 3 = sqrt 6`` or Vieta's relations
   between ``CRootOf``s), limited to :data:`~analysis.algebra.expressions.MAX_ZERO_BITS`.

>>> import sympy as sp
>>> is_zero(sp.sqrt(2) * sp.sqrt(3) - sp.sqrt(6)), is_zero(sp.sqrt(2) - sp.Rational(99, 70))
(True, False)
>>> is_zero(sp.sqrt(sp.Mul(sp.I + 1, sp.I - 1, evaluate=False)) - sp.I * sp.sqrt(2))   # on the cut
True
"""

from __future__ import annotations

import math

import flint
import sympy as sp

from ..result import AnalysisError
from .expressions import (FORMAL_MAX_TERMS, MAX_ZERO_BITS, Undecided, _atom_closure, _atoms_of, _bounds,
                          _deep_recursion, _guess_rational, _I, _ir, _MINUS1, _n, _neg, _Node, _rational_root,
                          _rootof_node, _short, _sub, _TooBig, degree_bound)
from .reader import as_expr


class _Algebra:
    """Caches shared by the exact decisions about one expression or mask."""

    def __init__(self):
        self._enc: dict = {}         # prec -> {node: acb}
        self._conjm: dict = {}
        self._rbc: dict = {}         # real by construction
        self._zero: dict = {}        # node -> (bool, how)
        self._real: dict = {}        # node -> bool (exactly real)
        self._roots: dict = {}       # k -> root atoms of the mask (partners for conjugates)
        self._depth: dict = {}
        self._croots: dict = {}      # (coeffs, prec) -> flint root balls
        self._space: _FormalSpace | None = None
        self.identities: list[str] = []
        self.methods: set = set()    # how the zeros were proven ("formal", "separation")

    def register(self, nodes) -> None:
        for node in nodes:
            for a in _atoms_of(node):
                if a[0] == "root":
                    lst = self._roots.setdefault(a[2], [])
                    if a not in lst:
                        lst.append(a)

    def depth(self, node) -> int:
        """Nesting depth of roots (0 for an expression without roots)."""
        if node in self._depth:
            return self._depth[node]
        kind = node[0]
        if kind in ("add", "mul"):
            out = max(self.depth(t) for t in node[1])
        elif kind == "pow":
            out = self.depth(node[1])
        elif kind == "root":
            out = self.depth(node[1]) + 1
        elif kind == "cjroot":
            out = max(self.depth(node[1]), self.depth(node[2])) + 1
        else:
            out = 0
        self._depth[node] = out
        return out

    # -- enclosures -------------------------------------------------------------------------
    def enclose(self, node, prec: int) -> flint.acb:
        memo = self._enc.setdefault(prec, {})
        return self._enclose(node, prec, memo)

    def _enclose(self, node, prec: int, memo: dict) -> flint.acb:
        if node in memo:
            return memo[node]
        kind = node[0]
        if kind == "root":
            out = self._enclose_root(node, prec, memo)
        elif kind == "cjroot":
            out = self._enclose(_n("root", node[1], node[3]), prec, memo).conjugate()
        elif kind == "rootof":
            out = self._rootof_ball(node, prec)
        else:
            with flint.ctx.workprec(prec):
                if kind == "q":
                    out = flint.acb(flint.fmpq(node[1].numerator, node[1].denominator))
                elif kind == "i":
                    out = flint.acb(0, 1)
                elif kind == "add":
                    out = flint.acb(0)
                    for t in node[1]:
                        out += self._enclose(t, prec, memo)
                elif kind == "mul":
                    out = flint.acb(1)
                    for t in node[1]:
                        out *= self._enclose(t, prec, memo)
                elif kind == "pow":
                    b, n = self._enclose(node[1], prec, memo), node[2]
                    out = b ** n if n >= 0 else 1 / b ** (-n)
                else:  # pragma: no cover
                    raise AssertionError(kind)
        memo[node] = out
        return out

    def _enclose_root(self, node, prec: int, memo: dict) -> flint.acb:
        base, k = node[1], node[2]
        b = self._enclose(base, prec, memo)
        with flint.ctx.workprec(prec):
            if b.real > 0 or not b.imag.contains(0) or not b.real < 0:
                return b.root(k)      # off the cut (or a base near 0: Arb's ball covers it)
        # the ball straddles the branch cut (negative reals): decide exactly where the base is
        if self.is_real(base):
            with flint.ctx.workprec(prec + 16):
                mag = (-b.real).root(k)
                return flint.acb(mag) * flint.acb(0, flint.arb.pi() / k).exp()
        p = prec
        while b.imag.contains(0):       # proven non-real: a finer ball leaves the axis
            p *= 2
            if p > MAX_ZERO_BITS:
                raise Undecided(f"cannot enclose {_short(node)}: its base is too close to the "
                                "branch cut")
            b = self.enclose(base, p)
        with flint.ctx.workprec(prec):
            return b.root(k)

    def _complex_roots(self, coeffs, prec: int):
        key = (coeffs, prec)
        if key not in self._croots:
            with flint.ctx.workprec(prec):
                f = flint.fmpz_poly(list(reversed(coeffs)))
                self._croots[key] = [r for r, _m in f.complex_roots()]
        return self._croots[key]

    def _rootof_ball(self, node, prec: int) -> flint.acb:
        """The CRootOf as a complex ball: flint isolates all roots (disjoint balls); the one
        meeting sympy's (exact, rational) isolating box is it."""
        coeffs, root = node[1], node[3]
        iv = root._get_interval()
        for attempt in range(12):
            if hasattr(iv, "ax"):
                box = (sp.Rational(iv.ax), sp.Rational(iv.bx), sp.Rational(iv.ay), sp.Rational(iv.by))
            else:
                box = (sp.Rational(iv.a), sp.Rational(iv.b), sp.Integer(0), sp.Integer(0))
            re_lo, re_hi, im_lo, im_hi = (flint.arb(flint.fmpq(int(x.p), int(x.q))) for x in box)
            hits = [r for r in self._complex_roots(coeffs, prec)
                    if not (r.real < re_lo or r.real > re_hi or r.imag < im_lo or r.imag > im_hi)]
            # the true root lies in sympy's box and in one of flint's disjoint isolating balls: if
            # just one ball meets the box, it is that root's ball
            if len(hits) == 1:
                return hits[0]
            root.eval_rational(n=4 * attempt + 20)            # refines sympy's isolating box
            iv = root._get_interval()
        raise AnalysisError(f"could not match {sp.sstr(root)} to a certified root ball")  # pragma: no cover

    # -- reality and conjugates ---------------------------------------------------------------
    def real_by_construction(self, node) -> bool:
        """True when the value is real because only real operations on real values occur (no I,
        even or odd roots only of bases certified positive, real CRootOfs)."""
        if node in self._rbc:
            return self._rbc[node]
        kind = node[0]
        if kind == "q":
            out = True
        elif kind == "i":
            out = False
        elif kind in ("add", "mul"):
            out = all(self.real_by_construction(t) for t in node[1])
        elif kind == "pow":
            out = self.real_by_construction(node[1])
        elif kind == "root":
            # the principal root of a positive number is real (of a negative one it is not)
            out = self.real_by_construction(node[1]) and bool(self.enclose(node[1], 64).real > 0)
        elif kind == "rootof":
            out = bool(node[3].is_real)
        else:
            out = False
        self._rbc[node] = out
        return out

    def is_real(self, node) -> bool:
        """Exactly: is the value real? (``x - conj(x) = 0`` by the zero test.)"""
        if node in self._real:
            return self._real[node]
        if self.real_by_construction(node):
            out = True
        elif not self.enclose(node, 64).imag.contains(0):
            out = False
        else:
            out = self.zero(_sub(node, self.conj(node)))[0]
        self._real[node] = out
        return out

    def conj(self, node):
        """An expression for the complex conjugate (module docstring, "Complex conjugates")."""
        if node in self._conjm:
            return self._conjm[node]
        kind = node[0]
        if kind == "q" or self.real_by_construction(node):
            out = node
        elif kind == "i":
            out = _neg(node)
        elif kind in ("add", "mul"):
            out = (kind, tuple(self.conj(t) for t in node[1]))
        elif kind == "pow":
            out = ("pow", self.conj(node[1]), node[2])
        elif kind == "root":
            out = self._conj_root(node)
        elif kind == "cjroot":
            out = _n("root", node[1], node[3])
        elif kind == "rootof":
            out = self._conj_rootof(node)
        else:  # pragma: no cover
            raise AssertionError(kind)
        out = out if isinstance(out, _Node) else _Node(out)
        self._conjm[node] = out
        return out

    def _conj_rootof(self, node):
        coeffs, index, root = node[1], node[2], node[3]
        prec = 64
        while prec <= 1 << 14:
            cb = self._rootof_ball(node, prec).conjugate()
            n = len(coeffs) - 1
            hits = []
            for j in range(n):
                other = _rootof_node(sp.CRootOf(root.poly, j))
                if self._rootof_ball(other, prec).overlaps(cb):
                    hits.append(other)
            if len(hits) == 1:
                if hits[0][2] != index:
                    self.identities.append(f"conj(CRootOf(.., {index})) = "
                                           f"CRootOf(.., {hits[0][2]})")
                return hits[0]
            prec *= 4
        raise Undecided(f"cannot identify the conjugate of {sp.sstr(root)}")  # pragma: no cover

    def _conj_root(self, node):
        base, k = node[1], node[2]
        cbase = self.conj(base)
        try:
            out = self._conj_root_rewrite(node, base, cbase, k)
        except Undecided:           # a rewrite that cannot be proven is not made
            out = None
        return out if out is not None else _n("cjroot", base, cbase, k)

    def _conj_root_rewrite(self, node, base, cbase, k):
        b = self.enclose(base, 128)
        if b.contains(0):
            return None
        if b.imag.contains(0) and self.is_real(base):
            if b.real > 0:
                return node
            if b.real < 0 and k == 2:
                self.identities.append("conj(sqrt(b)) = -sqrt(b) for b < 0")
                return _neg(node)
            if b.real < 0 and k == 4:
                self.identities.append("conj(b^(1/4)) = -I b^(1/4) for b < 0")
                return _n("mul", (_MINUS1, _I, node))
            return None
        cb = self.enclose(cbase, 128)
        r = self.enclose(node, 128)
        for other in self._roots.get(k, []):
            # partners no deeper than node: every recursion (enclosures on the branch cut, rewrites
            # of conjugates) then goes to strictly smaller depth, so it terminates
            if other == node or self.depth(other) > self.depth(node):
                continue
            if not self.enclose(other[1], 128).overlaps(cb):
                continue
            if not self.zero(_sub(other[1], cbase))[0]:
                continue
            # conj(r)^k = conj(b) = other^k: conj(r) / other is a k-th root of unity
            with flint.ctx.workprec(128):
                q = r.conjugate() / self.enclose(other, 128)
                units = [flint.acb(0, 2 * flint.arb.pi() * j / k).exp() for j in range(k)]
                meet = [j for j, u in enumerate(units) if q.overlaps(u)]
                ok = len(meet) == 1 and q.rad() < math.sin(math.pi / k) / 2
            if not ok or 4 * meet[0] % k:
                continue
            # zeta = 1, I, -1, -I
            factor = {0: (), 1: (_I,), 2: (_MINUS1,), 3: (_MINUS1, _I)}[4 * meet[0] // k]
            self.identities.append(f"conj(b^(1/{k})) = zeta b'^(1/{k}), b' = conj(b) proven")
            return _n("mul", factor + (other,)) if factor else other
        # |b|^2 = R = rho^k rational: conj(r) = rho / r
        m = self.enclose(_n("mul", (base, cbase)), 256)
        R = _guess_rational(m.real) if m.real > 0 and m.imag.contains(0) else None
        rho = _rational_root(R, k) if R is not None else None
        if rho is not None and self.zero(_n("add", (_n("mul", (base, cbase)), _n("q", -R))))[0]:
            self.identities.append(f"conj(b^(1/{k})) = {rho} / b^(1/{k}) (|b|^2 = {R} proven)")
            return _n("mul", (_n("q", rho), _n("pow", node, -1)))
        return None

    # -- the zero test --------------------------------------------------------------------------
    def zero(self, node) -> tuple[bool, dict]:
        """``(is_zero, how)`` decided rigorously (module docstring); :class:`Undecided` when out of
        reach."""
        if node in self._zero:
            return self._zero[node]
        out = None
        for prec in (64, 256):
            if not self.enclose(node, prec).contains(0):
                out = (False, {"how": f"Arb ball at {prec} bits excludes 0", "prec": prec})
                break
        if out is None and self._formal_zero(node):
            out = (True, {"how": "formal identity in the atoms", "method": "formal", "prec": 256})
        if out is None:
            out = self._separation_zero(node)
        if out[0]:
            self.methods.add(out[1]["method"])
        self._zero[node] = out
        return out

    def _formal_zero(self, node) -> bool:
        atoms = _atoms_of(node)
        sp_ = self._space
        if sp_ is None or any(a not in sp_.index for a in atoms):
            merged = list(sp_.atoms) if sp_ is not None else []
            have = set(merged)
            merged += [a for a in atoms if a not in have]
            sp_ = self._space = _FormalSpace(self, merged)
        try:
            n, _d = sp_.convert(node)
            if n.is_zero():
                return True
            return sp_.reduce(n).is_zero()
        except (_TooBig, Undecided):   # no formal proof: the next step decides
            return False

    def prepare(self, nodes) -> None:
        """One formal space for all the atoms of ``nodes`` (so that its cache is shared)."""
        seen: set = set()
        out: dict = {a: None for a in (self._space.atoms if self._space is not None else [])}
        for node in nodes:
            _atom_closure(node, out, seen)
        if self._space is None or len(out) > len(self._space.atoms):
            self._space = _FormalSpace(self, list(out))

    def _separation_zero(self, node, start_prec: int = 96) -> tuple[bool, dict]:
        prec = start_prec
        with flint.ctx.workprec(128):
            U, L = _bounds(node, {})
            U = max(U.upper(), flint.arb(1))
            L = L.upper()
            D = degree_bound(node)
            # |x| >= 2^-log2_sep if x != 0
            log2_sep = (L.log() + (D - 1) * U.log()) / flint.arb(2).log()
            need = int(math.ceil(float(log2_sep.upper()))) + 32
        while True:
            x = self.enclose(node, prec) if prec <= 4096 else self._enclose(node, prec, {})
            if not x.contains(0):
                return False, {"how": f"Arb ball at {prec} bits excludes 0", "prec": prec}
            if prec >= need:
                with flint.ctx.workprec(prec):
                    sep = flint.arb(2) ** (-(need - 32))
                    if abs(x) < sep:
                        return True, {"how": f"|x| < 2^-{need - 32} (root-separation bound: "
                                             f"degree <= {D}) at {prec} bits",
                                      "method": "separation", "prec": prec, "degree_bound": D}
            if need > MAX_ZERO_BITS and prec >= 4096:
                raise Undecided(f"cannot decide exactly whether {_short(node)} is zero: it is not a "
                                f"formal identity in its atoms and the root-separation bound "
                                f"(degree <= {D}) needs {need} bits (> {MAX_ZERO_BITS})")
            prec = min(4 * prec, max(need + 64, 128)) if prec < need else 2 * prec


class _FormalSpace:
    """Polynomials with integer coefficients in the atoms of a set of expressions."""

    def __init__(self, alg: _Algebra, atoms: list):
        self.alg = alg
        self.atoms = atoms
        self.index = {a: j for j, a in enumerate(atoms)}
        names = tuple(f"t{j}" for j in range(max(len(atoms), 1)))
        self.ctx = flint.fmpz_mpoly_ctx.get(names, "degrevlex")
        self.gens = self.ctx.gens()
        self.one = self.ctx.constant(1)
        self.memo: dict = {}
        self.relations: dict = {}

    def _check(self, *polys) -> None:
        if sum(len(p) for p in polys) > FORMAL_MAX_TERMS:
            raise _TooBig

    def _nonzero_value(self, node) -> None:
        """A divisor must be nonzero at the atom values (a proof, or an error)."""
        if not self.alg.enclose(node, 256).contains(0):
            return
        if self.alg.zero(node)[0]:
            raise AnalysisError(f"division by zero: {_short(node)} = 0")

    def convert(self, node):
        """``(n, d)``: the value is ``n(tau) / d(tau)`` with ``d(tau) != 0``."""
        if node in self.memo:
            return self.memo[node]
        kind = node[0]
        if node in self.index:
            out = (self.gens[self.index[node]], self.one)
        elif kind == "q":
            out = (self.ctx.constant(node[1].numerator), self.ctx.constant(node[1].denominator))
        elif kind == "add":
            n, d = self.convert(node[1][0])
            for t in node[1][1:]:
                n2, d2 = self.convert(t)
                if d == d2:
                    n = n + n2
                elif d2.is_constant() and d.is_constant():
                    a, b = int(d.coefficient(0)), int(d2.coefficient(0))
                    g = math.gcd(a, b)
                    n, d = n * (b // g) + n2 * (a // g), d * (b // g)
                else:
                    self._check(n, d, n2, d2)
                    g = d.gcd(d2)
                    if g.is_one():
                        n, d = n * d2 + n2 * d, d * d2
                    else:
                        a, b = d2 / g, d / g
                        n, d = n * a + n2 * b, d * a
                self._check(n, d)
            out = (n, d)
        elif kind == "mul":
            n, d = self.one, self.one
            for t in node[1]:
                n2, d2 = self.convert(t)
                if len(n) * len(n2) > FORMAL_MAX_TERMS or len(d) * len(d2) > FORMAL_MAX_TERMS:
                    raise _TooBig
                n, d = n * n2, d * d2
            out = (n, d)
        elif kind == "pow":
            n, d = self.convert(node[1])
            e = node[2]
            if e < 0:
                self._nonzero_value(node[1])
                n, d, e = d, n, -e
            if e > 1 and max(len(n), len(d)) ** min(e, 4) > FORMAL_MAX_TERMS:
                raise _TooBig
            out = (n ** e, d ** e)
        else:  # pragma: no cover  (atoms are all in the index)
            raise AssertionError(kind)
        self.memo[node] = out
        return out

    def _relation(self, atom):
        """``(k, p, c)`` with ``c t^k = p`` at the atom values (``c`` a nonzero integer) or None."""
        if atom in self.relations:
            return self.relations[atom]
        rel = None
        if atom[0] == "i":
            rel = (2, self.ctx.constant(-1), 1)
        elif atom[0] in ("root", "cjroot"):
            base, k = (atom[1], atom[2]) if atom[0] == "root" else (atom[2], atom[3])
            try:
                p, c = self.convert(base)
            except _TooBig:
                p, c = None, None
            if c is not None and c.is_constant():
                rel = (k, p, int(c.coefficient(0)))
        self.relations[atom] = rel
        return rel

    def reduce(self, n):
        """Normal form of ``n`` (up to a nonzero integer factor) modulo the relations."""
        for atom in reversed(self.atoms):       # roots before the atoms of their bases
            k = {"i": 2, "root": atom[-1], "cjroot": atom[-1]}.get(atom[0])
            if k is None or n.is_zero() or n.degrees()[self.index[atom]] < k:
                continue        # (only atoms of n: their bases are sub-expressions of the test)
            rel = self._relation(atom)
            if rel is None:
                continue
            v = self.index[atom]
            k, p, c = rel
            groups: dict = {}
            for mon, coef in n.to_dict().items():
                mon = list(mon)
                e = mon[v]
                mon[v] = e % k
                groups.setdefault(e // k, {})
                groups[e // k][tuple(mon)] = groups[e // k].get(tuple(mon), 0) + int(coef)
            M = max(groups)
            out = self.ctx.constant(0)
            for m, terms in groups.items():
                part = self.ctx.from_dict(terms)
                if m:
                    if len(part) * len(p) ** min(m, 3) > FORMAL_MAX_TERMS:
                        raise _TooBig
                    part = part * p ** m
                out = out + part * (c ** (M - m))
                self._check(out)
            n = out
        return n


def enclose(e, prec: int = 128) -> flint.acb:
    """A rigorous complex Arb ball containing the value of the algebraic expression ``e``
    (principal branches, as sympy defines them).

    >>> x = enclose(sp.sqrt(2)); x.real.overlaps(flint.arb(2).sqrt()), x.imag.is_zero(), x.rad() < 2**-120
    (True, True, True)
    """
    with _deep_recursion():
        node = _ir(as_expr(e), {})
        alg = _Algebra()
        alg.register([node])
        return alg.enclose(node, prec)


def is_zero(e) -> bool:
    """Exactly: is the algebraic expression ``e`` zero? (See the module docstring.)"""
    with _deep_recursion():
        node = _ir(as_expr(e), {})
        alg = _Algebra()
        alg.register([node])
        return alg.zero(node)[0]
