"""Bad input raises gam.GamError (a ValueError) with a clear message: wrong shapes, wrong
dtypes, NaN and infinity, arrays beyond the work budget, values that are not JSON; never a
crash, a hang or a NaN result."""

import math

import gam
import numpy as np
import pytest

SPEC = {"method": "ccm-additive", "poses": [{"position": [0, 0, 0]}, {"position": [1, 0, 0]}]}
M = np.tile(np.eye(4), (3, 1, 1))
X = np.zeros((3, 3))


def nested(depth):
    v = []
    for _ in range(depth):
        v = [v]
    return v


def test_gam_error_is_value_error():
    assert issubclass(gam.GamError, ValueError)


@pytest.mark.parametrize(
    "call,message",
    [
        (lambda: gam.transform_points(M, np.zeros((3, 2))), r"`points` must have shape \(N, 3\)"),
        (lambda: gam.transform_points(np.zeros((3, 3, 3)), X), r"shape \(N, 4, 4\)"),
        (lambda: gam.transform_points(M, np.zeros((4, 3))), "3 poses for 4 points"),
        (lambda: gam.transform_points(M, X.astype(complex)), "must hold real numbers"),
        (lambda: gam.transform_points(M, np.array([["a", "b", "c"]])), "must hold real numbers"),
        (lambda: gam.transform_points(M, [[1, 2], [3]]), "not an array of numbers|real numbers"),
        (lambda: gam.transform_points(M, np.full((3, 3), np.nan)), r"`points\[0, 0\]` is NaN"),
        (lambda: gam.transform_points(np.where(np.eye(4) == 1, np.inf, 0.0)[None], X[:1]), "inf"),
        (lambda: gam.transform_points(2 * M, X), r"`matrices_or_poses\[0\]` is not a rigid motion"),
        (lambda: gam.transform_points(np.diag([1.0, 1, -1, 1]), X), "not a rigid motion.*reflection"),
        (lambda: gam.transform_points([gam.Pose.identity(), "x"], X[:2]), "not a Pose"),
        (lambda: gam.Pose.from_matrix(np.eye(3)), r"shape \(4, 4\)"),
        (lambda: gam.Pose.from_quaternion([0, 0, 0, 0]), "non-zero"),
        (lambda: gam.Pose.from_quaternion([1, 0, 0]), r"shape \(4,\)"),
        (lambda: gam.Pose.from_axis_angle([0, 0, 0], 1.0), "axis"),
        (lambda: gam.Pose.from_axis_angle([0, 0, 1], math.inf), "finite"),
        (lambda: gam.Pose.from_quaternion([1, 0, 0, 0], [0, math.nan, 0]), "NaN"),
        (lambda: gam.Pose.from_motor({"1": 0}), "singular"),
        (lambda: gam.Pose.from_motor({"e5": 1}), "not a blade"),
        (lambda: gam.Pose.from_dual_quaternion([1, 0, 0, 0, 1, 0, 0, 0]), "Pl"),
        (lambda: gam.build(SPEC).sample(np.array([[0.5]])), "1-D"),
        (lambda: gam.build(SPEC).sample([0.5, 2.0]), "outside the motion's parameter range"),
        (lambda: gam.build(SPEC).sample([math.nan]), "NaN"),
        (lambda: gam.build(SPEC).sample([0.5], body_points=[1, 2, 3]), r"shape \(P, 3\)"),
        (lambda: gam.interpolate({"method": "ccm-additive", "poses": [{"position": [0, math.nan, 0]}, {}]}), "finite"),
        (lambda: gam.interpolate({"method": "ccm-additive", "poses": [{"position": [0, 2**70, 0]}, {}]}), "64 bits"),
        (lambda: gam.interpolate({"method": object()}), "not a JSON value"),
        (lambda: gam.interpolate({1: 2}), "keys must be strings"),
        (lambda: gam.pose(nested(200)), "nested"),
        (lambda: gam.prove("e1 = e1", assume=[1]), "list of strings"),
        (lambda: gam.eval("e1", scalar="nope"), "invalid value 'nope' for '--scalar <S>'"),
    ],
)
def test_bad_input(call, message):
    with pytest.raises(gam.GamError, match=message):
        call()


def test_budget_of_sampling(monkeypatch):
    # a cubic additive sample is about 25 units (gam::budget::Tableau): 600 fit in 2e4, 1000 do not
    monkeypatch.setenv("GAM_WORK_BUDGET", "2e4")
    m = gam.build(SPEC)
    with pytest.raises(gam.GamError, match="sampling 1 body points of degree-3 segments at 1000 values needs about"):
        m.sample(np.zeros(1000))
    with pytest.raises(gam.GamError, match="sampling 100 body points"):
        m.sample(np.zeros(10), body_points=np.zeros((100, 3)))
    assert m.sample(np.zeros(600))["matrix"].shape == (600, 4, 4)


def test_budget_of_transform_points(monkeypatch):
    monkeypatch.setenv("GAM_WORK_BUDGET", "10")
    with pytest.raises(gam.GamError, match="transforming 11 points needs about"):
        gam.transform_points(np.eye(4), np.zeros((11, 3)))
    assert gam.transform_points(np.eye(4), np.zeros((10, 3))).shape == (10, 3)


def test_other_threads_run_during_long_calls():
    # the interpreter is detached: a Python thread makes progress while Rust samples
    import threading

    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(1)

    th = threading.Thread(target=tick)
    th.start()
    try:
        gam.build(SPEC).sample(np.linspace(0, 1, 50000))
    finally:
        stop.set()
        th.join()
    assert len(ticks) > 100
