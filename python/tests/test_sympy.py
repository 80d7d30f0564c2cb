"""Symbolic round trip: `gam.eval(scalar="poly")` coefficients and `gam.prove` normal forms
parse in sympy and agree with sympy's own algebra.

The builders name coefficient symbols `S`, `S12`, ...: `S` is also sympy's singleton
registry (`sympy.S`), and `sympy.sympify("S*x")` reads it as that object, not a symbol. So
parse with `sympy.parse_expr(text, local_dict=...)`, giving every name a Symbol first
(`symbols_of` below), as docs/python.md says."""

import re

import gam
import sympy


def symbols_of(*texts):
    names = set()
    for t in texts:
        names.update(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", t))
    return {n: sympy.Symbol(n) for n in names}


def parse(text, local):
    return sympy.parse_expr(text, local_dict=local)


def test_eval_poly_parses_and_matches_sympy():
    out = gam.eval("(a*e1 + b*e2)*(c*e1 + S*e2)", algebra="g3", scalar="poly")
    local = symbols_of(*out.values())
    a, b, c, s = (local[n] for n in "abcS")
    got = {k: parse(v, local) for k, v in out.items()}
    # (a e1 + b e2)(c e1 + S e2) = ac + bS + (aS - bc) e12, by hand
    assert sympy.expand(got["1"] - (a * c + b * s)) == 0
    assert sympy.expand(got["e12"] - (a * s - b * c)) == 0
    assert set(got) == {"1", "e12"}


def test_the_S_clash_is_real():
    # why the local dict is needed: sympify maps "S" to sympy's singleton registry
    assert sympy.sympify("S") is sympy.S
    assert parse("S", {"S": sympy.Symbol("S")}) == sympy.Symbol("S")


def test_even_element_symbols_and_reverse_product():
    # rev(X) X of a general even element of g3: a scalar, the quaternion norm
    out = gam.eval("0", algebra="g3", scalar="poly")
    assert out == {}
    out = gam.eval("rev(S + S12*e12 + S13*e13 + S23*e23)*(S + S12*e12 + S13*e13 + S23*e23)", algebra="g3", scalar="poly")
    local = symbols_of(*out.values())
    want = sum(local[n] ** 2 for n in ["S", "S12", "S13", "S23"])
    assert list(out) == ["1"] and sympy.expand(parse(out["1"], local) - want) == 0


def test_prove_witness_normal_form_parses():
    out = gam.prove('let X = vector("x"); X*X = 1', algebra="g3")
    assert out["holds"] is False
    nf = out["witness"]["normal_form"]
    local = symbols_of(nf)
    x1, x2, x3 = local["x1"], local["x2"], local["x3"]
    # X*X - 1 = x1^2 + x2^2 + x3^2 - 1, already a normal form with no hypotheses
    assert sympy.expand(parse(nf, local) - (x1**2 + x2**2 + x3**2 - 1)) == 0
    point = out["witness"]["point"]
    assert parse(nf, local).subs({local[k]: v for k, v in point.items()}) != 0


def test_prove_under_hypothesis_agrees_with_sympy_groebner():
    # a*e1 = b*e1 follows from a = b; a*a*e1 = e1 does not follow from a != 0
    assert gam.prove("a*e1 = b*e1", algebra="g3", assume=["a = b"])["holds"] is True
    out = gam.prove("a*a*e1 = e1", algebra="g3", assume=["a*b = 1"])
    nf = parse(out["witness"]["normal_form"], symbols_of(out["witness"]["normal_form"]))
    a, b = sympy.symbols("a b")
    g = sympy.groebner([a * b - 1], a, b, order="grevlex")
    assert out["holds"] is False and g.reduce(a * a - 1)[1] != 0
    assert sympy.expand(g.reduce(nf)[1] - g.reduce(a * a - 1)[1]) == 0
