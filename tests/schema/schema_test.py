#!/usr/bin/env python3
"""Real reports and sweep rows against the JSON Schemas cdvp installs.

schema_test.py CDVP SCHEMA_DIR report LEVEL ALGORITHM
    runs `cdvp run` at --fidelity LEVEL on board.algorithm ALGORITHM
    (all_pairs or grid) and validates its report against
    run-report.schema.json;
schema_test.py CDVP SCHEMA_DIR presets BOARDS_DIR
    a report of every level (fast, cycle, analytic, auto; rtl where a
    built-in variant serves) on both boards and every preset in BOARDS_DIR,
    each validated against run-report.schema.json, its config.fidelity the
    level asked for and auto's fidelity_choice present;
schema_test.py CDVP SCHEMA_DIR bullet
    the same for `cdvp bullet --report` (a report with a 'bullet' section);
schema_test.py CDVP SCHEMA_DIR sweep RECORD
    runs a sweep of two ok points and a refused one (--record RECORD, full or
    compact) and validates every row of its sweep.csv against
    sweep-row.schema.json, and the manifest's format_version.

Each mode also takes the document it validated, removes a required field (or
sets a wrong format_version) and requires the schema to refuse it, so the
test fails when the schema stops requiring what the writers promise.
"""
import concurrent.futures
import copy
import csv
import json
import os
import subprocess
import sys
import tempfile

try:
    import jsonschema
except ImportError:
    sys.exit("schema test: python3-jsonschema is missing (scripts/setup.sh installs it)")


def fail(message):
    sys.exit("schema test: " + message)


def validator(schema_dir, name):
    path = os.path.join(schema_dir, name)
    with open(path, encoding="utf-8") as f:
        schema = json.load(f)
    jsonschema.Draft7Validator.check_schema(schema)
    return jsonschema.Draft7Validator(schema)


def check(valid, document, what):
    errors = sorted(valid.iter_errors(document), key=lambda e: list(e.absolute_path))
    if errors:
        first = errors[0]
        where = "/".join(str(p) for p in first.absolute_path) or "(top level)"
        fail(f"{what}: {len(errors)} errors against the schema; the first at {where}: {first.message}")


def refused(valid, document, change, what):
    """The schema must refuse `document` after `change` (a function on a copy)."""
    damaged = copy.deepcopy(document)
    change(damaged)
    if valid.is_valid(damaged):
        fail(f"the schema accepts {what}")


def cdvp(binary, args, cwd):
    result = subprocess.run([binary] + args, cwd=cwd, capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"cdvp {' '.join(args)} exited with {result.returncode}: {result.stderr.strip()}")


def read_json(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def check_report(valid, report, what):
    check(valid, report, what)
    if report["format_version"] != 2:
        fail(f"{what}: format_version {report['format_version']}")
    refused(valid, report, lambda r: r.pop("format_version"), "a report without format_version")
    refused(valid, report, lambda r: r.update(format_version=1), "a report of format_version 1")
    if "resources" in report["config"]:
        timing = lambda r: r["config"]["resources"]["timing"]
        refused(valid, report, lambda r: timing(r).pop("fmax_from"), "a timing without fmax_from")
        refused(valid, report, lambda r: timing(r)["pieces"]["lane"].update(path_ns=0), "a piece's path of 0 ns")
        refused(valid, report, lambda r: r["summary"].update(timing_warning=7), "a timing_warning that is not text")
    refused(valid, report, lambda r: r["summary"].pop("mean_total_ns"), "a report without summary.mean_total_ns")
    refused(valid, report, lambda r: r["frames"][0].pop("pairs"), "a frame without pairs")
    refused(valid, report, lambda r: r["config"].pop("fidelity"), "a report without config.fidelity")


# A built-in RTL variant (CDVP_RTL_VARIANTS), so the rtl level compiles nothing.
RTL_BOARD = ["--board", "adm-xrc-ii", "--m", "8", "--fifo-depth", "15", "--pair-buffer", "128"]


def report_mode(binary, schema_dir, work, level, algorithm):
    valid = validator(schema_dir, "run-report.schema.json")
    board = RTL_BOARD if level == "rtl" else ["--board", "adm-xrc-ii", "--m", "4"]
    cdvp(binary, ["run", "--scene", "spheres", "--objects", "300", "--frames", "3", "--baseline", "sap", "-q",
                  "--fidelity", level, "-c", "board.algorithm=" + algorithm, "--report", "report.json"] + board, work)
    report = read_json(os.path.join(work, "report.json"))
    what = f"the report at --fidelity {level} on board.algorithm {algorithm}"
    check_report(valid, report, what)
    ran = (report["config"]["fidelity"], report["config"]["settings"]["board.algorithm"]["value"])
    if ran != (level, algorithm):
        fail(f"{what} ran {ran[0]} on {ran[1]}")
    print(f"{what} ({len(report['frames'])} frames) validates; without a required field it does not")


PRESET_LEVELS = ["fast", "cycle", "analytic", "auto"]


def presets_mode(binary, schema_dir, work, boards_dir):
    valid = validator(schema_dir, "run-report.schema.json")
    presets = sorted(name[:-5] for name in os.listdir(boards_dir) if name.endswith(".json"))
    if not presets:
        fail(f"no presets in {boards_dir}")
    runs = [(preset, algorithm, level) for preset in presets for algorithm in ("all_pairs", "grid")
            for level in PRESET_LEVELS]
    runs.append(("adm-xrc-ii", "all_pairs", "rtl"))

    def one(preset, algorithm, level):
        name = f"{preset}.{algorithm}.{level}.json"
        board = RTL_BOARD[2:] if level == "rtl" else ["--m", "4"]
        cdvp(binary, ["run", "--board", os.path.join(boards_dir, preset + ".json"), "--scene", "spheres",
                      "--objects", "200", "--frames", "2", "-q", "--fidelity", level,
                      "-c", "board.algorithm=" + algorithm, "--report", name] + board, work)
        return name

    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        names = list(pool.map(lambda r: one(*r), runs))
    for (preset, algorithm, level), name in zip(runs, names):
        report = read_json(os.path.join(work, name))
        what = f"the report at --fidelity {level} on {preset} (board.algorithm {algorithm})"
        check(valid, report, what)
        if report["config"]["fidelity"] != level:
            fail(f"{what} records config.fidelity {report['config']['fidelity']!r}")
        if level == "auto":
            choice = report.get("fidelity_choice")
            if choice is None:
                fail(f"{what} has no fidelity_choice")
            if choice["analytic_frames"] + choice["fast_frames"] != len(report["frames"]):
                fail(f"{what}: fidelity_choice counts {choice['analytic_frames']} + {choice['fast_frames']} frames "
                     f"of {len(report['frames'])}")
            refused(valid, report, lambda r: r.pop("fidelity_choice"), "an auto report without fidelity_choice")
        elif "fidelity_choice" in report:
            fail(f"{what} has a fidelity_choice")
    print(f"{len(runs)} reports (every level, both boards, {len(presets)} presets) validate")


def bullet_mode(binary, schema_dir, work):
    valid = validator(schema_dir, "run-report.schema.json")
    cdvp(binary, ["bullet", "--scene", "boxes", "--objects", "100", "--frames", "3", "--board", "adm-xrc-ii",
                  "--m", "4", "-q", "--report", "report.json"], work)
    report = read_json(os.path.join(work, "report.json"))
    if "bullet" not in report:
        fail("cdvp bullet's report has no 'bullet' section")
    check_report(valid, report, "cdvp bullet's report")
    print("cdvp bullet's report validates; without a required field it does not")


def sweep_mode(binary, schema_dir, work, record):
    valid = validator(schema_dir, "sweep-row.schema.json")
    # m = 32 needs 192 block RAMs of the device's 144: a refused point.
    cdvp(binary, ["sweep", "--board", "adm-xrc-ii", "--set", "m=2,4,32", "--set", "objects=40", "--frames", "3",
                  "--baseline", "sap", "--record", record, "--out", "res", "-q"], work)
    manifest = read_json(os.path.join(work, "res", "sweep.json"))
    if manifest.get("format_version") != 3:
        fail(f"the manifest's format_version is {manifest.get('format_version')!r}, expected 3")
    with open(os.path.join(work, "res", "sweep.csv"), encoding="utf-8", newline="") as f:
        rows = [{k: v for k, v in row.items() if v != ""} for row in csv.DictReader(f)]
    statuses = sorted(row.get("status", "") for row in rows)
    if statuses != ["ok", "ok", "refused"]:
        fail(f"the sweep's rows have statuses {statuses}, expected two ok and one refused")
    for row in rows:
        check(valid, row, f"sweep row {row.get('point')} (--record {record})")
    ok = next(row for row in rows if row["status"] == "ok")
    no = next(row for row in rows if row["status"] == "refused")
    refused(valid, ok, lambda r: r.pop("format_version"), "a row without format_version")
    refused(valid, ok, lambda r: r.pop("mean_total_ns"), "an ok row without mean_total_ns")
    refused(valid, ok, lambda r: r.update(checksum="not hex"), "a row with a malformed checksum")
    refused(valid, ok, lambda r: r.update(mean_total_ns="fast"), "a row whose mean_total_ns is no number")
    refused(valid, no, lambda r: r.pop("reason"), "a refused row without its reason")
    print(f"{len(rows)} rows of a sweep (--record {record}) validate; damaged ones do not")


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    binary, schema_dir, mode = os.path.abspath(argv[1]), os.path.abspath(argv[2]), argv[3]
    with tempfile.TemporaryDirectory() as work:
        if mode == "report" and len(argv) == 6:
            report_mode(binary, schema_dir, work, argv[4], argv[5])
        elif mode == "presets" and len(argv) == 5:
            presets_mode(binary, schema_dir, work, os.path.abspath(argv[4]))
        elif mode == "bullet" and len(argv) == 4:
            bullet_mode(binary, schema_dir, work)
        elif mode == "sweep" and len(argv) == 5:
            sweep_mode(binary, schema_dir, work, argv[4])
        else:
            sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
