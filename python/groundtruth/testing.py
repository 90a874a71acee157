"""groundtruth.testing: assertions for your own test suite (pytest, unittest, hypothesis).

    from groundtruth.testing import assert_matches_reference

    def test_my_thermal_erosion():
        assert_matches_reference(my_step, "erosion.thermal", heights, cell_size=10, iterations=20)

assert_matches_reference runs groundtruth.check on the cheap path (no pictures, descriptors or
timing repetitions: quick=True unless told otherwise) and raises AssertionError listing each failing
check with its value, its bound and its error model, so a failing property test says what broke.
"""

from . import check

__all__ = ["assert_matches_reference"]


def _line(failed):
    bound = failed.get("threshold")
    return (f"  {failed['name']}: {failed.get('value')!r}"
            f"{'' if bound is None else f' > bound {bound!r}'} — {failed.get('detail', '')}")


def assert_matches_reference(model, algorithm, heights=None, **kwargs):
    """Passes when groundtruth.check(model, algorithm, heights, **kwargs) ends pass, warn or
    inconclusive; otherwise raises AssertionError naming the case's outcome and its failing checks.
    Returns the Result."""
    kwargs.setdefault("quick", True)
    result = check(model, algorithm, heights, **kwargs)
    if result.status in ("pass", "warn", "inconclusive"):
        return result
    lines = [f"{algorithm}: {result.status}" + (f": {result.error}" if result.error else "")]
    lines += [_line(failed) for failed in result.failed()]
    raise AssertionError("\n".join(lines))
