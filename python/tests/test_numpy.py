"""The numpy API against independent formulas: the quaternion's rotation matrix and
Rodrigues' formula written here, point maps by 4x4 matrices with numpy, composition as a
matrix product, finite differences of sampled positions against `velocities`, and
`Motion.sample` against `gam.interpolate`'s samples."""

import math

import gam
import numpy as np
import pytest

RNG = np.random.default_rng(20261203)


def quat_matrix(q, t):
    """The rigid matrix of the unit quaternion [w, x, y, z] (Hamilton) and translation t."""
    w, x, y, z = np.asarray(q, float) / np.linalg.norm(q)
    r = np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ])
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = r, t
    return m


def rodrigues(axis, angle, t):
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    m = np.eye(4)
    m[:3, :3] = np.eye(3) + math.sin(angle) * kx + (1 - math.cos(angle)) * kx @ kx
    m[:3, 3] = t
    return m


def random_poses(n):
    q = RNG.normal(size=(n, 4))
    t = RNG.normal(size=(n, 3)) * 5
    return q, t


def test_quaternion_to_matrix():
    for q, t in zip(*random_poses(50)):
        p = gam.Pose.from_quaternion(q, t)
        np.testing.assert_allclose(p.matrix, quat_matrix(q, t), rtol=0, atol=1e-14)
        qq = p.quaternion
        assert qq[0] >= 0 and abs(np.linalg.norm(qq) - 1) < 1e-15
        unit = q / np.linalg.norm(q) * np.sign(q[0])
        np.testing.assert_allclose(qq, unit, atol=1e-15)
        np.testing.assert_allclose(p.position, t, atol=1e-14)


def test_axis_angle_and_matrix_round_trip():
    for _ in range(30):
        axis, angle, t = RNG.normal(size=3), RNG.uniform(-3, 3), RNG.normal(size=3)
        m = rodrigues(axis, angle, t)
        p = gam.Pose.from_axis_angle(axis, angle, t)
        np.testing.assert_allclose(p.matrix, m, atol=1e-14)
        np.testing.assert_allclose(gam.Pose.from_matrix(m).matrix, m, atol=1e-14)
        # the motor and the dual quaternion read back as the same pose
        np.testing.assert_allclose(gam.Pose.from_motor(p.motor).matrix, m, atol=1e-14)
        np.testing.assert_allclose(gam.Pose.from_dual_quaternion(p.dual_quaternion).matrix, m, atol=1e-14)


def test_properties_equal_gam_pose():
    pose = {"position": [1, 2, 3], "quaternion": [0.5, 0.5, -0.5, 0.5]}
    want = gam.pose(pose)
    p = gam.Pose.from_quaternion(pose["quaternion"], pose["position"])
    assert p.motor == want["motor"]
    assert p.quaternion.tolist() == want["quaternion"]
    assert p.position.tolist() == want["position"]
    assert p.dual_quaternion.tolist() == want["dual_quaternion"]
    np.testing.assert_allclose(p.matrix, want["matrix"], rtol=0, atol=0)


def test_composition_order():
    (qa, qb), (ta, tb) = random_poses(2)
    a, b = gam.Pose.from_quaternion(qa, ta), gam.Pose.from_quaternion(qb, tb)
    ma, mb = quat_matrix(qa, ta), quat_matrix(qb, tb)
    # a * b applies a first: as matrices acting on columns, M_b @ M_a
    np.testing.assert_allclose((a * b).matrix, mb @ ma, atol=1e-13)
    np.testing.assert_allclose(a.then(b).matrix, mb @ ma, atol=1e-13)
    np.testing.assert_allclose(a.inverse().matrix, np.linalg.inv(ma), atol=1e-13)
    np.testing.assert_allclose((a * a.inverse()).matrix, np.eye(4), atol=1e-13)
    x = RNG.normal(size=(5, 3))
    np.testing.assert_allclose((a * b).transform_points(x), b.transform_points(a.transform_points(x)), atol=1e-12)


def test_transform_points_against_numpy():
    n = 20000
    q, t = random_poses(n)
    m = np.stack([quat_matrix(qi, ti) for qi, ti in zip(q[:200], t[:200])] * (n // 200))
    x = RNG.normal(size=(n, 3)) * 3
    want = np.einsum("nij,nj->ni", m, np.hstack([x, np.ones((n, 1))]))[:, :3]
    got = gam.transform_points(m, x)
    assert got.shape == (n, 3) and got.dtype == np.float64
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-13)
    # one matrix for every point, one point under every matrix, Poses, a list of Poses
    np.testing.assert_allclose(gam.transform_points(m[0], x), x @ m[0, :3, :3].T + m[0, :3, 3], atol=1e-13)
    np.testing.assert_allclose(gam.transform_points(m, x[0]), m[:, :3, :3] @ x[0] + m[:, :3, 3], atol=1e-13)
    poses = [gam.Pose.from_matrix(mi) for mi in m[:10]]
    np.testing.assert_allclose(gam.transform_points(poses, x[:10]), want[:10], atol=1e-13)
    np.testing.assert_allclose(gam.transform_points(poses[0], x[:3]), poses[0].transform_points(x[:3]), atol=0)
    # non-contiguous and integer inputs
    np.testing.assert_allclose(gam.transform_points(m[::2], x[::2]), want[::2], atol=1e-13)
    assert gam.transform_points(np.eye(4, dtype=np.int64), np.arange(6).reshape(2, 3)).tolist() == [[0, 1, 2], [3, 4, 5]]
    assert gam.transform_points(np.zeros((0, 4, 4)), np.zeros((0, 3))).shape == (0, 3)


SPEC = {
    "method": "ccm-additive",
    "poses": [{"position": [0, 0, 0]}, {"position": [1, 0, 0.5], "axis": [0, 0, 2], "angle": 1.2},
              {"position": [1, 1, 0], "quaternion": [0.5, 0.5, -0.5, 0.5]}],
    "samples": 9,
    "body_points": [[0, 0, 0], [0.5, -1, 2]],
}


@pytest.mark.parametrize("method", ["ccm-additive", "ccm-multiplicative", "juttler-spline", "wl-quadratic", "hexanion-linear"])
def test_sample_equals_interpolate(method):
    spec = dict(SPEC, method=method)
    out = gam.interpolate(spec)
    t = np.array([s["t"] for s in out["samples"]])
    s = gam.build(spec).sample(t)
    for k in ["matrix", "points", "velocities", "angular_velocity"]:
        assert s[k].tolist() == [x[k] for x in out["samples"]], k
    assert s["t"].tolist() == t.tolist()


@pytest.mark.parametrize("method", ["ccm-additive", "ccm-multiplicative", "juttler-q-motion", "wl-linear"])
def test_velocities_are_derivatives(method):
    m = gam.build(dict(SPEC, method=method))
    h = 1e-6
    t = np.linspace(0.03, 0.97, 18)  # not at the join t = 0.5 (one-sided there)
    s = m.sample(t)
    fd = (m.sample(t + h)["points"] - m.sample(t - h)["points"]) / (2 * h)
    np.testing.assert_allclose(s["velocities"], fd, rtol=1e-6, atol=1e-6)
    # the points are the sampled matrices applied to the body points, and rotate with the
    # angular velocity: dR/dt R^T = [omega]x
    bp = np.array(SPEC["body_points"], float)
    for i in range(len(t)):
        np.testing.assert_allclose(s["points"][i], bp @ s["matrix"][i, :3, :3].T + s["matrix"][i, :3, 3], atol=1e-12)
    dr = (m.sample(t + h)["matrix"][:, :3, :3] - m.sample(t - h)["matrix"][:, :3, :3]) / (2 * h)
    w = np.einsum("nij,nkj->nik", dr, s["matrix"][:, :3, :3])
    omega = np.stack([w[:, 2, 1], w[:, 0, 2], w[:, 1, 0]], axis=1)
    np.testing.assert_allclose(s["angular_velocity"], omega, rtol=1e-6, atol=1e-6)


def test_sample_other_body_points_and_many_t():
    m = gam.build(SPEC)
    t = np.linspace(0, 1, 20001)  # above the parallel threshold
    s = m.sample(t, body_points=[[1, 2, 3]])
    assert s["points"].shape == (20001, 1, 3)
    serial = [m.sample(t[i:i + 1], body_points=[[1, 2, 3]])["points"][0] for i in (0, 777, 20000)]
    assert [s["points"][i].tolist() for i in (0, 777, 20000)] == [x.tolist() for x in serial]
    assert m.parameters == [0.0, 0.5, 1.0]
    assert m.body_points.tolist() == SPEC["body_points"]


def test_pickle_pose():
    import pickle

    p = gam.Pose.from_axis_angle([1, 2, 3], 0.7, [4, 5, 6])
    assert pickle.loads(pickle.dumps(p)).matrix.tolist() == p.matrix.tolist()
