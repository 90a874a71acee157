"""The tables a notebook plots: a case's checks, a sweep's runs, an A/B comparison's metrics, as
pandas DataFrames built from the files the driver writes (report.json, sweep.json, ab.json), so
that Python's tables are the command line's. pandas is optional (groundtruth._optional)."""

import json

from . import _optional

CHECK_COLUMNS = ["status", "value", "bound", "loose_bound", "expected", "reason"]


def checks_frame(checks, feature="Result.checks_table"):
    """One row per check, indexed by its name: status, value, bound (the check's threshold; NaN for
    an info value without one), loose_bound, expected (the expectation list's outcome, if any) and
    reason (the expectation's reason, else the check's error model or why it was skipped)."""
    pandas = _optional.require("pandas", feature)
    rows = [{"name": check["name"], "status": check["status"],
             "value": float("nan") if check.get("value") is None else check["value"],
             "bound": check.get("threshold", float("nan")), "loose_bound": check.get("loose_threshold", float("nan")),
             "expected": check.get("expected", ""), "reason": check.get("expectation") or check.get("detail", "")}
            for check in checks]
    return pandas.DataFrame(rows, columns=["name", *CHECK_COLUMNS]).set_index("name")


def typed_value(text):
    """A parameter value as text (a sweep table's, a BMI config file's), back as an int, float or
    bool where it is one."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return {"true": True, "false": False}.get(text, text)


def sweep_frame(report_folder):
    """sweep.json as one row per run: the varied parameters, case, outcome, then every metric
    (seconds, cpu_ms, gpu_ms, each check's value, descriptor.<group>.<name>), NaN where a run has none."""
    pandas = _optional.require("pandas", "groundtruth.sweep")
    table = json.loads((report_folder / "sweep.json").read_text())
    rows = []
    for run in table["runs"]:
        row = {name: typed_value(value) for name, value in run.get("params", {}).items()}
        row.update(case=run["case"], outcome=run["outcome"])
        row.update({name: float("nan") if value is None else value for name, value in run.get("metrics", {}).items()})
        rows.append(row)
    return pandas.DataFrame(rows, columns=[*table["varied"], "case", "outcome", *table["metrics"]])


def ab_frame(report_folder):
    """ab.json as one row per metric, the metrics that moved first (as ab.html orders them): a, b and
    b_minus_a; the frame's attrs hold each side's case, assignments and outcome."""
    pandas = _optional.require("pandas", "groundtruth.ab")
    table = json.loads((report_folder / "ab.json").read_text())
    nan = float("nan")
    rows = [{"metric": row["name"], "a": nan if row["a"] is None else row["a"], "b": nan if row["b"] is None else row["b"],
             "b_minus_a": nan if row["b_minus_a"] is None else row["b_minus_a"]} for row in table["metrics"]]
    frame = pandas.DataFrame(rows, columns=["metric", "a", "b", "b_minus_a"]).set_index("metric")
    frame.attrs = {"a": table["a"], "b": table["b"], "difference": table.get("difference", {})}
    return frame
