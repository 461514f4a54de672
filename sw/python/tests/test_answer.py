"""cdvp.answer: the sweep's answer.csv as a DataFrame, from the sweep's table or its directory."""

import csv

import pandas as pd
import pytest

import cdvp

AXES = {"m": [1, 4], "objects": [20, 80]}
POINT_OPTIONS = {"board": "adm-xrc-ii", "scene": "spheres", "fidelity": "analytic", "frames": 2,
                 "baseline": ["sap", "soa"], "plots": False}


def test_answer_is_the_fastest_point_at_each_n_against_the_fastest_software(tmp_path):
    table = cdvp.sweep(AXES, tmp_path / "out", **POINT_OPTIONS)
    answer = cdvp.answer(table)
    with open(tmp_path / "out" / "answer.csv", newline="") as f:
        header = next(csv.reader(f))
    assert list(answer.columns) == header
    assert list(answer["objects"]) == [20, 80]
    for _, row in answer.iterrows():
        at_n = table[table["objects"] == row["objects"]]
        fastest = at_n.loc[at_n["mean_total_ns"].idxmin()]
        assert row["point"] == fastest["point"] and row["m"] == fastest["m"]
        software = "sap" if fastest["sap_mean_host_ns"] <= fastest["soa_mean_host_ns"] else "soa"
        assert row["software"] == software
        assert row["speedup"] == pytest.approx(fastest[software + "_mean_host_ns"] / fastest["mean_total_ns"])
        assert row["bound_by"] in ("bus", "memory", "compute", "host")
    # The same answer from the directory; text columns stay text where empty.
    again = cdvp.answer(tmp_path / "out")
    assert again.equals(answer)
    assert set(answer["time_crossover_how"]) <= {"measured", "interpolated", "none"}


def test_answer_of_no_sweep_is_refused(tmp_path):
    with pytest.raises(cdvp.InputError, match=r"answer.csv: no such file"):
        cdvp.answer(tmp_path)
    with pytest.raises(TypeError, match="expected a sweep's directory"):
        cdvp.answer(42)
    with pytest.raises(cdvp.InputError, match="not one cdvp.sweep\\(\\) returned"):
        cdvp.answer(pd.DataFrame({"m": [1]}))
