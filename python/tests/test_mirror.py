"""Every mirror function equals the `gam` command's `--json` output on the same inputs
(the examples of the CLI contract, shared/cli.md and docs/cli.md), and its errors carry the
command's `error:` message."""

import math

import gam
import pytest

# Floats: the extension and the binary run the same Rust code and, built with the same profile
# (as .ci/run builds both, with the dev profile), give the same bits: numbers are compared
# exactly. (The last-bit differences once seen in gam pose's screw and hexanion and gam
# trajectory's weights came with an extension built at opt-level 3 against a binary at
# opt-level 1; set GAM_BIN to a binary of the extension's profile.)
REL = 0.0


def close(a, b, at="$"):
    if isinstance(a, dict) and isinstance(b, dict):
        assert list(a) == list(b), f"{at}: keys {list(a)} != {list(b)}"
        for k in a:
            close(a[k], b[k], f"{at}.{k}")
    elif isinstance(a, list) and isinstance(b, list):
        assert len(a) == len(b), f"{at}: lengths {len(a)} != {len(b)}"
        for i, (x, y) in enumerate(zip(a, b)):
            close(x, y, f"{at}[{i}]")
    elif isinstance(a, float) and isinstance(b, float):
        assert math.isclose(a, b, rel_tol=REL, abs_tol=REL), f"{at}: {a!r} != {b!r}"
    elif isinstance(a, str) and isinstance(b, str) and a != b:
        try:
            x, y = float(a), float(b)
        except ValueError:
            raise AssertionError(f"{at}: {a!r} != {b!r}")
        assert math.isclose(x, y, rel_tol=REL, abs_tol=REL), f"{at}: {a!r} != {b!r}"
    else:
        assert type(a) is type(b) and a == b, f"{at}: {a!r} != {b!r}"

EVALS = [
    ("e1*e2*e3*einf*e0", "cga-null", "product", "rational"),
    ("einf*e0", "cga-null", "blade", "rational"),
    ("rev(e0*einf)", "cga-null", "product", "rational"),
    ("grade(e0inf, 0)", "cga-null", "product", "rational"),
    ("1/2*e1 + 0.25*e2", "g3", "blade", "rational"),
    ("inv(1 + 2*e1)", "g3", "blade", "rational"),
    ("(a*e1 + b*e2)*(a*e1 + b*e2)", "g3", "blade", "poly"),
    ("(x + 1)*e1 - y*y/2", "g3", "blade", "poly"),
    ("exp(e12*0.5)", "g3", "blade", "f64"),
    ("sqrt(2)", "g3", "blade", "mpfr:256"),
    ("exp(0.5*e12 + e1inf)", "g123inf", "blade", "f64"),
    ("dual(e0)", "pga3", "blade", "rational"),
    ("(a+b)*(a+b) == a*a + 2*a*b + b*b", "g3", "blade", "poly"),
    ("e1 == e2", "g3", "blade", "rational"),  # false: printed, then exit 1
    ("-e1", "g3", "blade", "rational"),
]


@pytest.mark.parametrize("expr,algebra,basis,scalar", EVALS)
def test_eval(cli, expr, algebra, basis, scalar):
    want = cli.json("eval", "--json", "--algebra", algebra, "--basis", basis, "--scalar", scalar, "--", expr)
    assert gam.eval(expr, algebra=algebra, basis=basis, scalar=scalar) == want


def test_eval_defaults_and_contract_example():
    assert gam.eval("e1*e2*e3*einf*e0", basis="product") == {"e123": "-2", "e0123inf": "1"}


@pytest.mark.parametrize(
    "algebra,basis,product",
    [("g3", "blade", "gp"), ("g3", "blade", "op"), ("cga-null", "product", "lc"), ("pga3", "blade", "rp")],
)
def test_table(cli, algebra, basis, product):
    want = cli.json("table", "--json", "--algebra", algebra, "--basis", basis, "--product", product)
    assert gam.table(algebra=algebra, basis=basis, product=product) == want


def without_time(v):
    return {k: x for k, x in v.items() if k != "time_ms"}


PROOFS = [
    ('let X = even("S"); (rev(X)*e0*X)*(rev(X)*e0*X) = 0', "cga-null", "product", ["rev(X)*X = 1"]),
    ('let X = vector("x"); X*X = sp(X, X)', "g3", "blade", []),
    ('let X = vector("x"); X*X = 1', "g3", "blade", []),  # does not hold: a witness
    ("a*e1 = b*e1", "g3", "blade", ["a = b"]),
    ("a*b*e1 = e1", "g3", "blade", ["a*b != 0"]),  # does not hold
]


@pytest.mark.parametrize("claim,algebra,basis,assume", PROOFS)
def test_prove(cli, claim, algebra, basis, assume):
    args = ["prove", "--json", "--algebra", algebra, "--basis", basis]
    for a in assume:
        args += ["--assume", a]
    want = cli.json(*args, "--", claim)
    got = gam.prove(claim, algebra=algebra, basis=basis, assume=assume)
    assert without_time(got) == without_time(want)
    assert isinstance(got["time_ms"], int)


def test_verify(cli):
    want = cli.json("verify", "--json", "--filter", "lemma-2.2")
    got = gam.verify(filter="lemma-2.2")
    assert len(got) == len(want) > 0
    assert [without_time(g) for g in got] == [without_time(w) for w in want]
    assert all(g["holds"] for g in got)


def test_verify_list(cli):
    want = cli.json("verify", "--json", "--list", "--filter", "lemma-2.2")
    got = gam.verify(filter="lemma-2.2", list=True)
    assert got == want
    assert [g["id"] for g in got] == [r["id"] for r in gam.verify(filter="lemma-2.2")]
    assert all("holds" not in g and isinstance(g["hypotheses"], str) for g in got)


POSES = [
    {"position": [1, 2, 3], "axis": [0, 0, 1], "angle": 1.5707963267948966},
    {"position": [1, 1, 0], "quaternion": [0.5, 0.5, -0.5, 0.5]},
    {"matrix": [[0, -1, 0, 2], [1, 0, 0, 1], [0, 0, 1, -1], [0, 0, 0, 1]]},
    {"motor": {"1": "1", "e1inf": "1", "e3inf": 0.5}},
    {"dual_quaternion": [1, 0, 0, 0, 0, 0.5, 0, 0]},
    {"hexanion": {"omega": [0, 0, 1], "m": [1, 0, 0]}},
    {"position": [0, 0, 2]},
    {},
]


@pytest.mark.parametrize("pose", POSES)
def test_pose(cli, pose):
    import json

    close(gam.pose(pose), cli.json("pose", "--json", json.dumps(pose)))


SEC52 = {
    "kind": "additive",
    "degree": 3,
    "start": {"position": [0, 0, 0], "axis": [1, 0, 0], "angle": 0, "velocity": [0, 0, 8],
              "angular_velocity": [-0.7853981633974483, 0, 0], "shape": 4, "gamma": [0.5, 0.5]},
    "end": {"position": [0, 10, 0], "axis": [1, 0, 0], "angle": -1.5707963267948966, "velocity": [0, 4, 0],
            "angular_velocity": [0.39269908169872414, 0, 0], "gamma": [1, -0.5]},
}
SEC51 = {
    "kind": "multiplicative",
    "degree": 3,
    "start": {"position": [0, 0, 0], "axis": [0, 0, 1], "angle": 0, "velocity": [1, 1, 1],
              "angular_velocity": [1, 2, 3], "shape": 1, "gamma": [0, 0]},
    "end": {"position": [8, 10, 12], "axis": [1, 2, 3], "angle": 1.959, "velocity": [1, 5, 3],
            "angular_velocity": [2, 1, 1]},
}


@pytest.mark.parametrize("spec", [SEC52, SEC51, dict(SEC51, kind="additive", degree=5)])
def test_hermite(cli, spec):
    assert gam.hermite(spec) == cli.json("hermite", "--json", "spec", files={"spec": spec})


def test_hermite_sec52_printed_value():
    # the contract's printed output (docs/cli.md), first control poses
    out = gam.hermite(SEC52)
    assert out["control_poses"][1] == {"1": "1.3333333333333333", "e23": "-0.5235987755982988",
                                       "e3inf": "5.333333333333333", "e123inf": "0.3333333333333333"}


KEYS = [
    {"position": [0, 0, 0]},
    {"position": [1, 0, 0.5], "axis": [0, 0, 2], "angle": 1.2},
    {"position": [1, 1, 0], "quaternion": [0.5, 0.5, -0.5, 0.5]},
    {"matrix": [[0, -1, 0, 2], [1, 0, 0, 1], [0, 0, 1, -1], [0, 0, 0, 1]]},
]
EX = {"method": "ccm-additive",
      "poses": [{"position": [0, 0, 0]}, {"position": [1, 0, 0], "axis": [0, 0, 1], "angle": 1.5707963267948966},
                {"position": [1, 1, 0], "quaternion": [0, 0, 0, 1]}],
      "samples": 2}
SPECS = [EX] + [
    {"method": m, "poses": KEYS, "samples": 7, "body_points": [[0, 0, 0], [0, 0, 1]]}
    for m in ["ccm-additive", "ccm-multiplicative", "juttler-q-motion", "juttler-trt", "juttler-minimal",
              "juttler-spline", "wl-linear", "wl-quadratic", "hexanion-linear"]
] + [
    {"method": "ccm-additive", "poses": KEYS[:3], "parameters": "chordal", "shape": 2, "gamma": [0.5, 0], "samples": 5},
    {"method": "juttler-spline", "poses": KEYS[:3], "parameters": [0, 1, 3], "samples": 4,
     "velocities": [{"velocity": [1, 0, 0], "angular_velocity": [0, 0, 1]}] * 3},
    {"method": "juttler-trt", "poses": KEYS[:3], "l1": 1, "samples": 3},
]


@pytest.mark.parametrize("spec", SPECS, ids=[f"{i}-{s['method']}" for i, s in enumerate(SPECS)])
def test_interpolate(cli, spec):
    assert gam.interpolate(spec) == cli.json("interpolate", "--json", "spec", files={"spec": spec})


@pytest.mark.parametrize("method", ["ccm-additive", "juttler-q-motion", "juttler-minimal", "juttler-spline"])
@pytest.mark.parametrize("point", [[1, 0, 0], [0.5, -2, 3.25]])
def test_trajectory(cli, method, point):
    spec = {"method": method, "poses": KEYS[:3]}
    text = ",".join(repr(float(x)) for x in point)
    want = cli.json("trajectory", "--json", "spec", "--point", text, files={"spec": spec})
    close(gam.trajectory(spec, point), want)
    close(gam.trajectory(spec, text), want)


# Errors: the same message as the command's `error:` line (the spec file is named `spec`, as
# the Python door names its spec).
BAD_SPECS = [
    ("hermite", dict(SEC52, degree=1)),
    ("hermite", {k: v for k, v in SEC52.items() if k != "end"}),
    ("hermite", dict(SEC52, kind="sideways")),
    ("hermite", dict(SEC52, start=dict(SEC52["start"], shape=-1))),
    ("interpolate", {"method": "ccm-additive", "poses": [{"position": [0, 0, 0]}]}),
    ("interpolate", {"method": "no-such-method", "poses": KEYS}),
    ("interpolate", {"method": "wl-linear", "poses": KEYS, "shape": 2}),
    ("interpolate", {"method": "ccm-additive", "poses": KEYS, "samples": 1}),
    ("interpolate", {"method": "ccm-additive", "poses": [{"position": [0, 0]}, {}]}),
    ("interpolate", {"method": "ccm-additive", "poses": [{"axis": [0, 0, 0], "angle": 1}, {}]}),
    ("interpolate", {"method": "ccm-additive", "poses": [{"quaternion": [0, 0, 0, 0]}, {}]}),
    ("interpolate", {"method": "ccm-additive", "poses": [{"matrix": [[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}, {}]}),
    ("interpolate", {"method": "ccm-additive", "poses": KEYS, "samples": 10**6, "body_points": [[0, 0, 0]] * 50}),
    ("interpolate", {"poses": KEYS}),
    ("interpolate", [1, 2]),
]


@pytest.mark.parametrize("command,spec", BAD_SPECS)
def test_spec_errors(cli, command, spec):
    want = cli.error(command, "--json", "spec", files={"spec": spec})
    with pytest.raises(gam.GamError) as e:
        getattr(gam, command)(spec)
    assert str(e.value) == want


@pytest.mark.parametrize(
    "args,call",
    [
        (["eval", "--json", "--algebra", "g3", "e7"], lambda: gam.eval("e7", algebra="g3")),
        (["eval", "--json", "--algebra", "g3", "1 +"], lambda: gam.eval("1 +", algebra="g3")),
        (["eval", "--json", "--algebra", "g3", "inv(e1 + e12)*0 + inv(1 + e1)"], lambda: gam.eval("inv(e1 + e12)*0 + inv(1 + e1)", algebra="g3")),
        (["eval", "--json", "--algebra", "nope", "e1"], lambda: gam.eval("e1", algebra="nope")),
        (["eval", "--json", "--basis", "sideways", "e1"], lambda: gam.eval("e1", basis="sideways")),
        (["eval", "--json", "--scalar", "mpfr:1", "e1"], lambda: gam.eval("e1", scalar="mpfr:1")),
        (["eval", "--json", "--scalar", "f64", "a*e1"], lambda: gam.eval("a*e1", scalar="f64")),
        (["table", "--json", "--product", "xx"], lambda: gam.table(product="xx")),
        (["prove", "--json", "--", "e1 = "], lambda: gam.prove("e1 = ")),
        (["prove", "--json", "--timeout", "-1", "--", "e1 = e1"], lambda: gam.prove("e1 = e1", timeout=-1)),
        (["verify", "--json", "--filter", "zzz-none"], lambda: gam.verify(filter="zzz-none")),
        (["pose", "--json", '{"position": [1, 2]}'], lambda: gam.pose({"position": [1, 2]})),
        (["pose", "--json", '{"motor": {"1": 0}}'], lambda: gam.pose({"motor": {"1": 0}})),
        (["pose", "--json", '{"dual_quaternion": [1, 0, 0, 0, 1, 0, 0, 0]}'],
         lambda: gam.pose({"dual_quaternion": [1, 0, 0, 0, 1, 0, 0, 0]})),
    ],
)
def test_option_and_input_errors(cli, args, call):
    want = cli.error(*args)
    with pytest.raises(gam.GamError) as e:
        call()
    assert str(e.value) == want


def test_trajectory_errors(cli):
    spec = {"method": "wl-linear", "poses": KEYS[:2]}
    want = cli.error("trajectory", "--json", "spec", "--point", "0,0,0", files={"spec": spec})
    with pytest.raises(gam.GamError) as e:
        gam.trajectory(spec, [0, 0, 0])
    assert str(e.value) == want
    ok = {"method": "ccm-additive", "poses": KEYS[:2]}
    want = cli.error("trajectory", "--json", "spec", "--point", "nan,0,0", files={"spec": ok})
    with pytest.raises(gam.GamError) as e:
        gam.trajectory(ok, "nan,0,0")
    assert str(e.value) == want
    with pytest.raises(gam.GamError, match="finite"):
        gam.trajectory(ok, [math.nan, 0, 0])
    with pytest.raises(gam.GamError, match="three finite numbers"):
        gam.trajectory(ok, [0, 0])


def test_budget_env(cli, monkeypatch):
    spec = {"method": "ccm-additive", "poses": KEYS, "samples": 1000}
    monkeypatch.setenv("GAM_WORK_BUDGET", "100")
    want = cli.error("interpolate", "--json", "spec", files={"spec": spec})
    with pytest.raises(gam.GamError) as e:
        gam.interpolate(spec)
    assert str(e.value) == want and "GAM_WORK_BUDGET" in want
