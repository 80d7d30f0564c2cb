"""`scalar=` of the motion functions mirrors `--scalar` of the commands (docs/cli.md,
"Precision of the motion commands"): the same JSON as `gam ... --json --scalar S`, exact
results as `"p/q"` strings under `"rational"`, against the independent fixture written with
Python's `fractions` (tests/fixtures/fractions/juttler_trajectory.py); `fractions.Fraction`
inputs are read exactly; refusals raise GamError with the command's message."""

import json
import pathlib
from fractions import Fraction

import gam
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
CASES = json.loads((ROOT / "tests" / "fixtures" / "fractions" / "juttler_trajectory.json").read_text())


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_rational_trajectory_is_the_fixture_and_the_cli(cli, case):
    got = gam.trajectory(case["spec"], case["point"], scalar="rational")
    assert got["segments"] == case["segments"]
    want = cli.json("trajectory", "--json", "--scalar", "rational", "spec.json", "--point", case["point"],
                    files={"spec.json": case["spec"]})
    assert got == want


@pytest.mark.parametrize("scalar", ["rational", "mpfr:128"])
def test_interpolate_and_pose_mirror_the_cli(cli, scalar):
    spec = dict(CASES[1]["spec"], samples=5, body_points=[[0.5, -1, 2]])
    want = cli.json("interpolate", "--json", "--scalar", scalar, "spec.json", files={"spec.json": spec})
    assert gam.interpolate(spec, scalar=scalar) == want
    pose = {"quaternion": [0.6, 0, 0, 0.8], "position": [1, "1/3", 0]}
    want = cli.json("pose", "--json", "--scalar", scalar, json.dumps(pose))
    assert gam.pose(pose, scalar=scalar) == want


def test_fractions_are_read_exactly():
    spec = {"method": "juttler-affine", "samples": 2,
            "poses": [{"position": [Fraction(1, 3), 0, 0]}, {"position": [1, Fraction(-2, 7), 0]}]}
    out = gam.interpolate(spec, scalar="rational")
    assert out["samples"][0]["points"] == [["1/3", "0", "0"]]
    assert out["samples"][1]["points"] == [["1", "-2/7", "0"]]
    curve = gam.trajectory(spec, [Fraction(1, 3), 0, 0], scalar="rational")["segments"][0]
    assert curve["points"][0] == ["2/3", "0", "0"]


def test_refusals_carry_the_command_message():
    spec = {"method": "wl-linear", "poses": [{"position": [0, 0, 0]}, {"position": [1, 0, 0]}]}
    with pytest.raises(gam.GamError, match="wl-linear is not exact over the rationals"):
        gam.interpolate(spec, scalar="rational")
    with pytest.raises(gam.GamError, match="invalid value 'poly' for '--scalar <S>'"):
        gam.interpolate(spec, scalar="poly")


def test_surface_mirrors_the_cli(cli):
    spec = CASES[0]["spec"]
    curve = {"points": [[Fraction(1, 2), 0, 0], [0, 1, 1]], "weights": [1, 2]}
    got = gam.surface(spec, curve, scalar="rational")
    want = cli.json("surface", "--json", "--scalar", "rational", "spec.json", "--curve", "curve.json",
                    files={"spec.json": spec, "curve.json": {"points": [["1/2", 0, 0], [0, 1, 1]], "weights": [1, 2]}})
    assert got == want
    assert got["segments"][0]["points"][0][0] == ["1/2", "0", "0"]
    f64 = gam.surface(spec, {"points": [[0.5, 0, 0], [0, 1, 1]], "weights": [1, 2]})
    assert f64["segments"][0]["degrees"] == got["segments"][0]["degrees"]
