"""fspm's statistics against scipy.stats on the same data."""
import numpy as np
import pytest
from scipy import stats

import fspm

RNG = np.random.default_rng(7)
A = RNG.normal(10.0, 2.0, size=14)
B = RNG.normal(11.5, 3.5, size=11)
ALTERNATIVES = ["two-sided", "less", "greater"]


def test_descriptive_statistics():
    assert fspm.mean(A) == pytest.approx(np.mean(A), rel=1e-14)
    assert fspm.variance(A) == pytest.approx(np.var(A, ddof=1), rel=1e-12)
    assert fspm.standard_deviation(A) == pytest.approx(np.std(A, ddof=1), rel=1e-12)
    low, high = fspm.mean_confidence_interval(A, 0.9)
    ref = stats.t.interval(0.9, len(A) - 1, loc=np.mean(A), scale=stats.sem(A))
    assert (low, high) == pytest.approx(ref, rel=1e-10)
    assert fspm.mean([1, 2, 3]) == 2.0  # lists and integers are converted


@pytest.mark.parametrize("alternative", ALTERNATIVES)
def test_student_and_welch_t_tests(alternative):
    for equal_var, fn in ((True, fspm.student_t_test), (False, fspm.welch_t_test)):
        r = fn(A, B, alternative=alternative)
        ref = stats.ttest_ind(A, B, equal_var=equal_var, alternative=alternative)
        assert r.t == pytest.approx(ref.statistic, rel=1e-10)
        assert r.p == pytest.approx(ref.pvalue, rel=1e-8)
        assert (r.n_a, r.n_b) == (len(A), len(B))
        assert r.estimate == pytest.approx(np.mean(A) - np.mean(B), rel=1e-12)
    va, vb = np.var(A, ddof=1) / len(A), np.var(B, ddof=1) / len(B)
    welch_df = (va + vb) ** 2 / (va ** 2 / (len(A) - 1) + vb ** 2 / (len(B) - 1))
    assert fspm.welch_t_test(A, B).df == pytest.approx(welch_df, rel=1e-12)
    assert fspm.student_t_test(A, B).df == len(A) + len(B) - 2


def test_t_test_confidence_interval():
    r = fspm.welch_t_test(A, B, level=0.99)
    se = np.sqrt(np.var(A, ddof=1) / len(A) + np.var(B, ddof=1) / len(B))
    half = stats.t.ppf(0.995, r.df) * se
    assert r.confidence_interval == pytest.approx((r.estimate - half, r.estimate + half), rel=1e-9)
    low, high = fspm.welch_t_test(A, B, alternative="less").confidence_interval
    assert low == -np.inf and np.isfinite(high)
    d = r.to_dict()
    assert d["p"] == r.p and d["confidence_interval"] == r.confidence_interval


@pytest.mark.parametrize("alternative", ALTERNATIVES)
def test_paired_t_test(alternative):
    b = A + RNG.normal(0.3, 0.5, size=len(A))
    r = fspm.paired_t_test(A, b, alternative=alternative)
    ref = stats.ttest_rel(A, b, alternative=alternative)
    assert r.t == pytest.approx(ref.statistic, rel=1e-10)
    assert r.p == pytest.approx(ref.pvalue, rel=1e-8)
    assert r.df == len(A) - 1
    assert r.estimate == pytest.approx(np.mean(A - b), rel=1e-12)


@pytest.mark.parametrize("alternative", ALTERNATIVES)
def test_mann_whitney_exact_and_with_ties(alternative):
    r = fspm.mann_whitney_u_test(A, B, alternative=alternative)
    ref = stats.mannwhitneyu(A, B, alternative=alternative, method="exact")
    assert r.exact and r.u == ref.statistic
    assert r.p == pytest.approx(ref.pvalue, rel=1e-10)
    ta, tb = np.round(A), np.round(B)  # ties: normal approximation with continuity correction
    r = fspm.mann_whitney_u_test(ta, tb, alternative=alternative)
    ref = stats.mannwhitneyu(ta, tb, alternative=alternative, method="asymptotic",
                             use_continuity=True)
    assert not r.exact and r.u == ref.statistic
    assert r.p == pytest.approx(ref.pvalue, rel=1e-10)
    r = fspm.mann_whitney_u_test(ta, tb, alternative=alternative, continuity_correction=False)
    ref = stats.mannwhitneyu(ta, tb, alternative=alternative, method="asymptotic",
                             use_continuity=False)
    assert r.p == pytest.approx(ref.pvalue, rel=1e-10)


def test_cohens_d():
    pooled = np.sqrt(((len(A) - 1) * np.var(A, ddof=1) + (len(B) - 1) * np.var(B, ddof=1))
                     / (len(A) + len(B) - 2))
    assert fspm.cohens_d(A, B) == pytest.approx((np.mean(A) - np.mean(B)) / pooled, rel=1e-12)


def test_statistics_errors():
    with pytest.raises(fspm.ParameterError, match="at least 1 values, got 0"):
        fspm.mean([])
    with pytest.raises(fspm.ParameterError):
        fspm.standard_deviation([1.0])
    with pytest.raises(fspm.ParameterError, match="sideways"):
        fspm.student_t_test(A, B, alternative="sideways")
    with pytest.raises(fspm.ParameterError, match=r"one-dimensional sample, got shape \(2, 2\)"):
        fspm.mean(np.ones((2, 2)))
    with pytest.raises(fspm.ParameterError):
        fspm.paired_t_test([1, 2, 3], [1, 2])
    with pytest.raises(TypeError):
        fspm.mean("abc")
