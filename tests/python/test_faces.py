# SPDX-License-Identifier: BSD-3-Clause
"""Issue 30, the faces users touch: quaternions in either order and back,
errors that name their cause, the spheroid's preconditions, a Pythonic
Index, batch_threads(), broadcast views without copies, type hints.

References are computed here with mpmath at 40 digits from the formulas
(the rotation of a quaternion, Q = R·diag(a²)·Rᵀ), never by pypw85."""

import __future__
import inspect
import math
import os
import pathlib
import pydoc
import subprocess
import sys
import tracemalloc
import types

import mpmath
import numpy as np
import pytest

import pypw85
import pypw85.d2
import pypw85.index

mpmath.mp.dps = 40
U = 2.0**-53


# ---------------------------------------------------------------------------
# Item 1: quaternions, (w, x, y, z) or (x, y, z, w), SciPy, and back.

def mp_rotation(w, x, y, z):
    """R(p) for p = (w, x, y, z) normalised, in mpmath: v ↦ p·v·p*."""
    w, x, y, z = (mpmath.mpf(float(t)) for t in (w, x, y, z))
    n = w * w + x * x + y * y + z * z
    w, x, y, z = (t / mpmath.sqrt(n) for t in (w, x, y, z))
    return mpmath.matrix([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def mp_form(a, r):
    """Q = R·diag(a²)·Rᵀ in mpmath, as 6 stored entries rounded to double."""
    d = mpmath.diag([mpmath.mpf(float(t)) ** 2 for t in a])
    m = r * d * r.T
    return np.array([float(m[i, j]) for i in range(3) for j in range(i, 3)])


def random_quaternions(n, seed):
    rng = np.random.default_rng(seed)
    p = rng.normal(size=(n, 4))
    return p / np.linalg.norm(p, axis=1)[:, None]


A = np.array([3.0, 1.5, 0.5])


def close_forms(q, ref):
    # pw85.h: each entry within u·|Q_k| + 2⁻¹⁰⁰·max a²; the reference is
    # itself rounded once (u·|Q_k|): 2u·max a² bounds both.
    return np.abs(q - ref).max() <= 2 * U * A.max() ** 2


def test_quaternion_scalar_first_and_last():
    """The same ellipsoid from (w, x, y, z) by default and from
    (x, y, z, w) with scalar_first=False; the wrong order is another
    ellipsoid (the silent mistake of the issue)."""
    for p in random_quaternions(20, 1):
        ref = mp_form(A, mp_rotation(*p))
        assert close_forms(pypw85.ellipsoid_quaternion(A, p), ref)
        xyzw = np.roll(p, -1)
        assert close_forms(
            pypw85.ellipsoid_quaternion(A, xyzw, scalar_first=False), ref)
    p = random_quaternions(20, 2)
    refs = np.array([mp_form(A, mp_rotation(*pk)) for pk in p])
    q = pypw85.ellipsoid_quaternion(A, np.roll(p, -1, axis=1),
                                    scalar_first=False)
    assert all(close_forms(qk, rk) for qk, rk in zip(q, refs))
    wrong = pypw85.ellipsoid_quaternion(A, np.roll(p, -1, axis=1))
    assert np.abs(wrong - refs).max() > 1.0
    with pytest.raises(TypeError):
        pypw85.ellipsoid_quaternion(A, p[0], scalar_first="no")
    # the same for principal_axes_quaternion (None, "no", [] and 0 were
    # taken as false or true)
    for flag in (None, "no", [], 0):
        with pytest.raises(TypeError, match="^scalar_first: expected a bool"):
            pypw85.principal_axes_quaternion(refs[0], scalar_first=flag)
    for f in (pypw85.ellipsoid_quaternion, pypw85.principal_axes_quaternion):
        assert "OVITO" in f.__doc__ and "SciPy" in f.__doc__
        assert "(x, y, z, w)" in f.__doc__


def test_scipy_rotation_accepted():
    transform = pytest.importorskip("scipy.spatial.transform")
    p = random_quaternions(10, 3)
    rot = transform.Rotation.from_quat(np.roll(p, -1, axis=1))  # x, y, z, w
    refs = np.array([mp_form(A, mp_rotation(*pk)) for pk in p])
    for q in (pypw85.ellipsoid_quaternion(A, rot),
              pypw85.ellipsoid_quaternion(A, rot, scalar_first=False),
              pypw85.ellipsoid_rotation(A, rot)):
        assert q.shape == (10, 6)
        # ellipsoid_rotation takes SciPy's matrix as given, orthonormal to
        # a few u only: Q moves by a few u·max a² (measured 7.1 at worst
        # on 300 rotations of this generator).
        assert np.abs(q - refs).max() <= 16 * U * A.max() ** 2
    one = pypw85.ellipsoid_quaternion(A, rot[0])
    assert close_forms(one, refs[0])


def column_error(r_out, r_ref):
    """max over j of the distance from column j of r_out to ± column j of
    r_ref (both mpmath)."""
    worst = 0.0
    for j in range(3):
        worst = max(worst, min(
            max(float(abs(r_out[i, j] - sign * r_ref[i, j]))
                for i in range(3)) for sign in (1, -1)))
    return worst


def test_principal_axes_quaternion_against_mpmath():
    """Forms built at 40 digits from known semi-axes (distinct: 3, 1.5,
    0.5) and quaternions, rounded: the semi-axes come back within 8u·a0
    (measured 1.7u on 300 forms of this generator) and each direction,
    up to its sign, within 16u (measured 7.2u: the rounding of Q turns
    the directions by a few u·‖Q‖/gap, the gaps of the a² being 6.75 and
    2 of 9); Q is rebuilt within 16u·‖Q‖ (measured 4.4u)."""
    p = random_quaternions(30, 4)
    for pk in p:
        r_ref = mp_rotation(*pk)
        q = mp_form(A, r_ref)
        a, pout = pypw85.principal_axes_quaternion(q)
        assert np.abs(a - A).max() <= 8 * U * A.max()
        assert pout[0] >= 0 and abs(np.dot(pout, pout) - 1) <= 8 * U
        assert column_error(mp_rotation(*pout), r_ref) <= 16 * U
        a2, last = pypw85.principal_axes_quaternion(q, scalar_first=False)
        assert np.array_equal(a2, a)
        assert np.array_equal(last, np.roll(pout, -1))
        back = pypw85.ellipsoid_quaternion(a, last, scalar_first=False)
        assert np.abs(back - q).max() <= 16 * U * A.max() ** 2
    qs = np.array([mp_form(A, mp_rotation(*pk)) for pk in p])
    a_many, p_many = pypw85.principal_axes_quaternion(qs.reshape(5, 6, 6))
    assert a_many.shape == (5, 6, 3) and p_many.shape == (5, 6, 4)
    for k in range(30):
        a1, p1 = pypw85.principal_axes_quaternion(qs[k])
        assert np.array_equal(a_many.reshape(30, 3)[k], a1)
        assert np.array_equal(p_many.reshape(30, 4)[k], p1)


# ---------------------------------------------------------------------------
# Items 2 and 4: the Index, its errors and its container protocol.

Q = np.array([1.0, 0.0, 0.0, 1.0, 0.0, 1.0])


def raised(f):
    with pytest.raises(pypw85.Error) as e:
        f()
    return e.value


def test_index_errors_name_the_cause():
    with pypw85.Index([3.0, 3.0, 3.0]) as index:
        index.insert([0, 1], [[0, 0, 0], [1, 1, 1]], Q)
        wide = [2.4, 0, 0, 1, 0, 1]
        e = raised(lambda: index.insert([5, 12], [[0, 0, 0], [0, 0, 0]],
                                        [Q, wide]))
        width = 2 * math.sqrt(2.4) * (1 + 2.0**-20)
        assert e.status == pypw85.EINVAL and e.id == 12 and e.item == 1
        assert "ellipsoid 12 (item 1 of 2)" in str(e)
        assert "2·√Q_00·(1 + 2⁻²⁰) = %.17g ≥ L_0 = 3" % width in str(e)
        e = raised(lambda: index.insert(1, [0, 0, 0], Q))
        assert e.id == 1 and "id 1 is already stored" in str(e)
        e = raised(lambda: index.insert([7, 7], [0, 0, 0], Q))
        assert e.item == 1 and "id 7 is already used by an earlier item" \
            in str(e)
        for call in (lambda: index.remove(9), lambda: index.get(9),
                     lambda: index.update(9, [0, 0, 0], Q)):
            e = raised(call)
            assert e.status == pypw85.EINVAL and "id 9 is not stored" \
                in str(e)
        e = raised(lambda: index.insert([3, 4], [[0, 0, 0], [np.nan, 0, 0]],
                                        Q))
        assert e.status == pypw85.EDOM and e.id == 4 and e.item == 1
        assert "centre = [nan, 0.0, 0.0] is not finite" in str(e)
        e = raised(lambda: index.insert(3, [0, 0, 0], [1, 2, 0, 1, 0, 1]))
        assert e.status == pypw85.ENOTPOSDEF and "not positive definite" \
            in str(e)
        e = raised(lambda: index.update(0, [1e10, 0, 0], Q))
        assert "|c_0| = 10000000000 > 2²⁹·L_0 = %.17g" % (2.0**29 * 3) \
            in str(e)
        e = raised(lambda: index.overlap_any([0, -1e10, 0], Q))
        assert e.status == pypw85.EINVAL and "|c_1| = 10000000000" in str(e)
        e = raised(lambda: index.within([0, 0, 0], Q, t=0.0))
        assert e.status == pypw85.EINVAL and "t = 0 is not > 0" in str(e)
        e = raised(lambda: index.overlapping_pairs(threads=0))
        assert "threads = 0 is not ≥ 1" in str(e)
        e = raised(lambda: index.overlapping_pairs(threads=2**31))
        assert e.status == pypw85.EINVAL and \
            "threads = 2147483648 is above 2³¹ − 1 (a C int)" in str(e)
        assert len(index) == 2  # every failed call left it unchanged
    e = raised(lambda: pypw85.Index([1.0, -2.0, 1.0]))
    assert e.status == pypw85.EINVAL and "box side L_1 = -2 is not > 0" \
        in str(e)
    e = raised(lambda: pypw85.Index([1.0, 2.0, np.inf]))
    assert e.status == pypw85.EDOM and "L_2 = inf is not finite" in str(e)
    # The bounds that keep sums of centres and sides finite (pw85_index.h).
    e = raised(lambda: pypw85.Index([1.0, 1e299, 1.0]))
    assert e.status == pypw85.EINVAL and \
        "box side L_1 = 1.0000000000000001e+299 is above 2⁹⁹² = " \
        "4.1855804968213567e+298" in str(e)
    e = raised(lambda: pypw85.d2.Index([2.0**993, 1.0]))
    assert e.status == pypw85.EINVAL and "rectangle side L_0 = " in str(e) \
        and "is above 2⁹⁹²" in str(e)
    for index in (pypw85.Index(), pypw85.d2.Index()):
        with index:
            dim = index._dim.dim
            centre, form = np.zeros(dim), np.eye(dim)[np.triu_indices(dim)]
            centre[-1] = -1e308
            e = raised(lambda: index.insert(0, centre, form))
            assert e.status == pypw85.EINVAL and "|c_%d| = 1e+308 > 2¹⁰²¹ = " \
                "2.2471164185778949e+307" % (dim - 1) in str(e)
            e = raised(lambda: index.overlap_any(centre, form))
            assert e.status == pypw85.EINVAL and "> 2¹⁰²¹" in str(e)
            assert len(index) == 0


def test_index_is_pythonic():
    assert "Index" in pypw85.__all__
    assert "class Index" in pydoc.render_doc(pypw85, renderer=pydoc.plaintext)
    with pypw85.Index([6.0, 6.0, 6.0]) as index:
        for bad in (7.9, True, 2.5, np.float64(3.0), np.array([1.0, 2.0]),
                    np.array([True, False]), "3", None):
            with pytest.raises(TypeError):
                index.insert(bad, [0, 0, 0], Q)
        with pytest.raises(TypeError):
            index.remove(1.0)
        with pytest.raises(ValueError):
            index.insert(-1, [0, 0, 0], Q)
        # one form (and one centre) over many ids
        ids = np.array([4, 2, 9], dtype=np.int32)
        centres = [[0, 0, 0], [2, 0, 0], [4, 0, 0]]
        index.insert(ids, centres, Q)
        for k, i in enumerate(ids):
            c, q = index.get(int(i))
            assert c.tolist() == centres[k] and q.tolist() == Q.tolist()
        index.insert(np.arange(10, 13), [1.0, 3.0, 3.0], Q)
        assert len(index) == 6
        assert list(index) == [2, 4, 9, 10, 11, 12]
        assert 9 in index and np.int64(9) in index and 3 not in index
        assert 9.0 not in index and True not in index and "9" not in index
        index.remove(9)
        assert 9 not in index and list(index) == [2, 4, 10, 11, 12]
        assert repr(index) == \
            "<pypw85.Index: periodic box (6, 6, 6), 5 ellipsoids>"
    assert repr(index) == "<pypw85.Index (closed)>"
    with pypw85.Index() as open_index:
        open_index.insert(0, [0, 0, 0], Q)
        assert repr(open_index) == "<pypw85.Index: open domain, 1 ellipsoid>"


# ---------------------------------------------------------------------------
# Item 3: the spheroid's preconditions.

def test_spheroid_preconditions():
    n = [0.0, 0.6, 0.8]
    for a, c, axis, rule in [(0.0, 2.0, n, "a = 0.0 is not > 0"),
                             (-1.0, 2.0, n, "a = -1.0 is not > 0"),
                             (1.0, 0.0, n, "c = 0.0 is not > 0"),
                             (1.0, 2.0, [0.0, 0.0, 0.0], "‖n‖² = 0.0"),
                             (1.0, 2.0, [0.0, 1.0, 1.0], "‖n‖² = 2.0")]:
        e = raised(lambda: pypw85.spheroid(a, c, axis))
        assert e.status == pypw85.EINVAL and rule in str(e)
    assert raised(lambda: pypw85.spheroid(1e200, 1.0, n)).status == \
        pypw85.ERANGE
    # within UNIT_TOL passes, as the constructors' quaternions
    f = math.sqrt(1 + 0.8 * pypw85.UNIT_TOL)
    pypw85.spheroid(1.0, 2.0, [0.0, 0.6 * f, 0.8 * f])
    a = np.array([1.0, 2.0, -3.0, 4.0])
    e = raised(lambda: pypw85.spheroid(a, 1.0, n))
    assert e.index == (2,) and "item (2,) of (4,)" in str(e)
    assert "a = -3.0 is not > 0" in str(e)
    assert e.statuses.tolist() == [0, 0, pypw85.EINVAL, 0]
    axes = np.array([n, n, [1.0, 1.0, 0.0]])
    e = raised(lambda: pypw85.spheroid(1.0, 2.0, axes))
    assert e.index == (2,) and "not a unit vector" in str(e)
    # Every item's status, whichever fails first; an item that breaks a
    # rule is never computed. (The statuses said 0 for items after the
    # first EINVAL, and after a non-finite one the items breaking a rule
    # were computed and reported 0.)
    q = np.full((4, 6), -7.0)
    a = np.array([-1.0, 1e200, np.nan, 1.0])
    e = raised(lambda: pypw85.spheroid(a, 1.0, n, q=q))
    assert e.status == pypw85.EINVAL and e.index == (0,)
    assert e.statuses.tolist() == [pypw85.EINVAL, pypw85.ERANGE,
                                   pypw85.EDOM, 0]
    assert "(3 of 4 failed): a = -1.0 is not > 0" in str(e)
    assert (q == -7.0).all()  # none computed
    a = np.array([np.nan, -1.0, 1e200, 1.0])
    e = raised(lambda: pypw85.spheroid(a, 1.0, n, q=q))
    assert e.status == pypw85.EDOM and e.index == (0,)
    assert e.statuses.tolist() == [pypw85.EDOM, pypw85.EINVAL,
                                   pypw85.ERANGE, 0]
    assert (q[:2] == -7.0).all()  # EDOM and EINVAL: untouched
    # ERANGE: written, as pw85_spheroid() writes it (a² = inf: inf and NaN)
    assert not np.isfinite(q[2]).any()
    assert np.array_equal(q[3], pypw85.spheroid(1.0, 1.0, n))


# ---------------------------------------------------------------------------
# Item 5: batch_threads() answers the count of a large batch.

def test_batch_threads_of_a_large_batch():
    openmp = pypw85.batch_threads(2, 512) == 2
    assert pypw85.batch_threads(3) == (3 if openmp else 1)
    assert pypw85.batch_threads(1) == 1
    assert pypw85.batch_threads(0, 2**56) == 1  # the cap of pw85.h
    code = "import pypw85; print(pypw85.batch_threads())"
    env = dict(os.environ, OMP_NUM_THREADS="2")
    out = subprocess.run([sys.executable, "-c", code], env=env, check=True,
                         capture_output=True, text=True).stdout
    assert int(out) == (2 if openmp else 1)
    with pytest.raises(ValueError):
        pypw85.batch_threads(0, 2**64)


# ---------------------------------------------------------------------------
# Item 6: a broadcast view is passed with stride 0, not copied.

def test_broadcast_view_is_not_copied():
    n = 100_000
    rng = np.random.default_rng(6)
    r12 = rng.uniform(-3, 3, (n, 3))
    q = np.array([1.0, 0.1, 0.0, 0.5, 0.0, 0.25])
    view = np.broadcast_to(q, (n, 6))
    assert view.strides == (0, 8)
    out = np.empty((n, 2))
    tracemalloc.start()
    pypw85.contact_function(r12, view, view, out)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    # A copy of one view is 4.8 MB; what remains is bookkeeping.
    assert peak < 200_000, peak
    ref = pypw85.contact_function(r12, np.ascontiguousarray(view), q)
    assert np.array_equal(out, ref)
    tracemalloc.start()
    result = pypw85.overlap(r12, view, view[:, None, :][:, 0])
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert peak < n * 4 + 200_000, peak  # the (n,) int result only
    assert np.array_equal(result, pypw85.overlap(r12, q, q))


# ---------------------------------------------------------------------------
# Item 9: type hints, py.typed, the public names.

def public_functions():
    for name in pypw85.__all__:
        obj = getattr(pypw85, name)
        if isinstance(obj, types.FunctionType):
            yield name, obj
    # Index's own members and those of its base (shared with d2.Index).
    members = {}
    for cls in reversed(pypw85.Index.__mro__[:-1]):
        members.update(vars(cls))
    for name, obj in members.items():
        if isinstance(obj, types.FunctionType) and (
                not name.startswith("_") or name in (
                    "__init__", "__len__", "__contains__", "__iter__",
                    "__repr__")):
            yield "Index." + name, obj
    import pypw85.legacy as legacy
    for name in legacy.__all__:
        obj = getattr(legacy, name)
        if isinstance(obj, types.FunctionType):
            yield "legacy." + name, obj


def test_type_hints_and_py_typed():
    names = []
    for name, f in public_functions():
        names.append(name)
        sig = inspect.signature(f)
        assert sig.return_annotation is not inspect.Signature.empty, name
        for p in sig.parameters.values():
            if p.name != "self" and p.kind not in (p.VAR_POSITIONAL,
                                                   p.VAR_KEYWORD):
                assert p.annotation is not inspect.Parameter.empty, \
                    (name, p.name)
    assert "contact_function" in names and "Index.insert" in names
    package = pathlib.Path(pypw85.__file__).parent
    assert (package / "py.typed").is_file()
    root = pathlib.Path(os.environ.get("PW85_SOURCE_ROOT",
                                       package.parents[2]))
    assert "'pypw85/py.typed'" in \
        (root / "bindings" / "python" / "meson.build").read_text()


def test_public_names_are_the_api():
    import pypw85.legacy as legacy
    for module, allowed in ((pypw85, {"index", "legacy"}), (legacy, set())):
        public = {name for name, obj in vars(module).items()
                  if not name.startswith("_")
                  and not isinstance(obj, types.ModuleType)
                  and not isinstance(obj, __future__._Feature)}
        assert public - set(module.__all__) - allowed == set(), module
    assert "not a bool" in pypw85.overlap.__doc__
    assert "result < 0" in pypw85.Index.overlap_any.__doc__


# ---------------------------------------------------------------------------
# Scalars: an integer beyond a double's range is a ValueError naming the
# argument (OverflowError escaped), a string or a container a TypeError
# (strings were parsed: aspect='123' read as [1, 2, 3]).

def test_scalar_conversions():
    q = pypw85.spheroid(1.0, 2.0, [0.0, 0.0, 1.0])
    r = [3.0, 0.0, 0.0]
    huge = 10**400
    with pytest.raises(ValueError, match="^lambda_: expected a real number "
                       "in the range of a double, got an integer of 401 "
                       "digits$"):
        pypw85.f(huge, r, q, q)
    with pytest.raises(ValueError, match="^a: expected a real number in "
                       "the range"):
        pypw85.spheroid(2**2000, 1.0, [0.0, 0.0, 1.0])
    # a bool, refused in the arrays, is refused as a scalar too (True was
    # read as λ = 1, as a radius of 1)
    for flag in (True, np.bool_(False)):
        with pytest.raises(TypeError, match="^lambda_: expected a real "
                           "number, got a bool"):
            pypw85.f(flag, r, q, q)
        with pytest.raises(TypeError, match="^c: expected a real number, "
                           "got a bool"):
            pypw85.spheroid(1.0, flag, [0.0, 0.0, 1.0])
    a = np.ones((4, 3))
    for options, error, text in [
            ({"target": huge}, ValueError, "pack: target: expected a real "
             "number in the range"),
            ({"time_limit": huge}, ValueError, "pack: time_limit: expected"),
            ({"aspect": [huge, 1, 1]}, ValueError, "pack: aspect: expected"),
            ({"target": "0.1"}, TypeError, "pack: target must be a real"),
            ({"time_limit": "1"}, TypeError, "pack: time_limit must be"),
            ({"aspect": "123"}, TypeError, "pack: aspect must be 3 real"),
            ({"aspect": {1: 1, 2: 2, 3: 3}}, TypeError, "pack: aspect must"),
            ({"axis": "001"}, TypeError, "pack: axis must be 3 real")]:
        with pytest.raises(error, match="^" + text):
            pypw85.pack(a, **options)
    index = pypw85.Index([1.0, 1.0, 1.0])
    index.insert(0, [0.5, 0.5, 0.5], [0.01, 0, 0, 0.01, 0, 0.01])
    for t, error in [("1", TypeError), (None, TypeError), ([1.0], TypeError),
                     (huge, ValueError)]:
        with pytest.raises(error, match="^t: expected a real number"):
            index.within([0.0, 0.0, 0.0], [0.01, 0, 0, 0.01, 0, 0.01], t)
        with pytest.raises(error, match="^t: expected a real number"):
            index.pairs_within(t)
        with pytest.raises(error, match="^t: expected a real number" if t
                           is not None else "^energy: u needs its threshold"):
            index.energy(u=lambda mu2: (0.0, 0.0), t=t)
        with pytest.raises(error, match="^eps: expected a real number"):
            index.energy(t)
    index.close()


# Arrays of the index and of micro: real numbers only, named (complex
# entries lost their imaginary parts with a warning, bools were read as 0
# and 1, strings failed with NumPy's message).
def test_real_arrays_named():
    from pypw85 import micro
    s = [0.01, 0.0, 0.0, 0.01, 0.0, 0.01]
    with pytest.raises(TypeError, match="^box: expected real numbers, got "
                       "an array of dtype bool"):
        pypw85.Index([True, True, True])
    with pytest.raises(TypeError, match="^box: expected real numbers"):
        pypw85.Index("abc")
    index = pypw85.Index([1.0, 1.0, 1.0])
    index.insert(0, [0.5, 0.5, 0.5], s)
    with pytest.raises(TypeError, match="^centres: expected real numbers, "
                       "got an array of dtype complex128"):
        index.overlap_any_many(np.zeros((1, 3)) + 1j, s)
    with pytest.raises(TypeError, match="^centre: expected real numbers"):
        index.overlap_any(np.array([0.5, 0.5, 0.5 + 1j]), s)
    index.close()
    with pytest.raises(TypeError, match="^centres: expected real numbers, "
                       "got an array of dtype complex128"):
        micro.voxel_image(np.zeros((1, 3)) + 1j, [s], [1.0, 1.0, 1.0], 4)
    with pytest.raises(TypeError, match="^q: expected real numbers"):
        micro.voxel_image(np.zeros((1, 3)), np.array([s]) + 0j,
                          [1.0, 1.0, 1.0], 4)
    with pytest.raises(TypeError, match="^sides: expected real numbers"):
        micro.voxel_image(np.zeros((1, 3)), [s], [1j, 1.0, 1.0], 4)
    # a bool flag ('no' was taken for periodic)
    with pytest.raises(TypeError, match="^periodic: expected a bool, got "
                       "str"):
        micro.voxel_image(np.zeros((1, 3)), [s], [1.0, 1.0, 1.0], 4,
                          periodic="no")


# Masked arrays: NumPy's conversions keep the values under a mask and drop
# the mask, so that a call used values the caller had set aside. Refused
# wherever an array enters, naming the argument; a masked array with no
# masked entry is its data.
def test_masked_entries_refused():
    from pypw85 import micro
    q1 = pypw85.spheroid(1.0, 0.5, [0.0, 0.0, 1.0])
    q2 = pypw85.spheroid(0.7, 0.2, [1.0, 0.0, 0.0])
    r = np.array([1.2, 0.3, 0.1])
    hidden = np.ma.masked_array(r, mask=[False, True, False])
    match = "^%s: a masked array with 1 masked entries"
    with pytest.raises(ValueError, match=match % "r12"):
        pypw85.contact_function(hidden, q1, q2)
    with pytest.raises(ValueError, match=match % "q2"):
        pypw85.overlap(r, q1, np.ma.masked_array(q2, mask=[0, 0, 0, 0, 0, 1]))
    with pytest.raises(ValueError, match=match % "r12"):  # a batch
        pypw85.contact_function(
            np.ma.masked_array([r, r], mask=[[0, 0, 0], [0, 1, 0]]), q1, q2)
    with pytest.raises(ValueError, match=match % "r12"):
        pypw85.d2.contact_function(
            np.ma.masked_array([1.0, 2.0], mask=[1, 0]), [1.0, 0.0, 1.0],
            [1.0, 0.0, 1.0])
    m = np.ma.masked_array(np.eye(3), mask=np.eye(3, dtype=bool) & False)
    m[1, 1] = np.ma.masked
    with pytest.raises(ValueError, match=match % "a"):
        pypw85.pack_sym(m)
    with pytest.raises(ValueError, match=match % "rot"):
        pypw85.ellipsoid_rotation([1.0, 1.0, 1.0], m)
    with pytest.raises(ValueError, match=match % "p"):
        pypw85.ellipsoid_quaternion(
            [1.0, 1.0, 1.0], np.ma.masked_array([0.0, 0.0, 0.0, 1.0],
                                                mask=[0, 0, 1, 0]),
            scalar_first=False)
    index = pypw85.Index([1.0, 1.0, 1.0])
    with pytest.raises(ValueError, match=match % "centres"):
        index.insert([0, 1], np.ma.masked_array(np.full((2, 3), 0.5),
                                                mask=[[0, 0, 0], [1, 0, 0]]),
                     [0.01, 0.0, 0.0, 0.01, 0.0, 0.01])
    with pytest.raises(ValueError, match=match % "ids"):
        index.insert(np.ma.masked_array([0, 1], mask=[0, 1]),
                     np.full((2, 3), 0.5), [0.01, 0.0, 0.0, 0.01, 0.0, 0.01])
    assert len(index) == 0  # nothing inserted by the refused calls
    index.close()
    image = np.ma.masked_array(np.full((2, 2, 2), -1, dtype=np.int32))
    image[0, 0, 0] = np.ma.masked
    with pytest.raises(ValueError, match=match % "image"):
        micro.phase_fraction(image)
    with pytest.raises(ValueError, match=match % "pack: semi_axes"):
        pypw85.pack(np.ma.masked_array(np.full((4, 3), 0.1),
                                       mask=np.eye(4, 3, dtype=bool) & (
                                           np.arange(3) == 0)), 0.1)
    # no masked entry: the data, as a plain array gives it
    whole = np.ma.masked_array(r, mask=False)
    assert (pypw85.contact_function(whole, q1, q2)
            == pypw85.contact_function(r, q1, q2)).all()
