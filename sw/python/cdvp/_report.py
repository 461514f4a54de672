"""A run's report as Python objects: its config, typed summary, frames and pairs."""

import io
from dataclasses import dataclass, field

import pandas as pd

# The phases of a frame in simulated time, as the report names them (sw/run/report_summary.h).
PHASES = ("upload", "start", "compute", "irq", "readback", "driver", "total")


@dataclass
class Baseline:
    """One software baseline's time a frame on the modelled host, and the board's speedup over it."""

    mean_host_ns: float
    p50_host_ns: float
    p99_host_ns: float
    max_host_ns: float
    mean_native_ns: float
    host_factor: float
    speedup: float


@dataclass
class Summary:
    """The report's summary: means over the frames after the warm-up (simulated time unless _native)."""

    frames: int
    warmup_frames: int
    frames_in_means: int
    too_few_frames: bool
    pairs: int
    mean_phase_ns: dict   # phase -> mean ns: upload, start, compute, irq, readback, driver, total
    total_ns: dict        # mean, p50, p99, max of the board's frame time
    mean_sim_wall_native_ns: float
    baselines: dict       # name -> Baseline
    extra_pairs: int      # against the float32 reference (a fixed-point format's)
    best_software: str = ""  # the baseline with the least mean frame time ("": none timed)

    @classmethod
    def from_json(cls, summary):
        baselines = {name: Baseline(**{key: b[key] for key in Baseline.__dataclass_fields__})
                     for name, b in summary["baselines"].items()}
        return cls(frames=summary["frames"], warmup_frames=summary["warmup_frames"],
                   frames_in_means=summary["frames_in_means"], too_few_frames=summary["too_few_frames"],
                   pairs=summary["pairs"],
                   mean_phase_ns={phase: summary[f"mean_{phase}_ns"] for phase in PHASES},
                   total_ns={stat: summary[f"{stat}_total_ns"] for stat in ("mean", "p50", "p99", "max")},
                   mean_sim_wall_native_ns=summary["mean_sim_wall_native_ns"],
                   baselines=baselines, extra_pairs=summary["extra_pairs"],
                   best_software=summary.get("best_software", ""))


@dataclass
class Report:
    """What one cdvp run wrote: `raw` is its JSON report as parsed, `pairs_csv` its pairs file's bytes."""

    config: dict
    summary: Summary
    frames: pd.DataFrame  # one row a frame; a baseline's times as columns sap_host_ns, sap_native_ns
    raw: dict = field(repr=False)
    pairs_csv: bytes = field(default=None, repr=False)

    @property
    def pairs(self):
        """The pairs of every frame (columns frame, a, b), or None if the run was not asked for them."""
        if self.pairs_csv is None:
            return None
        return pd.read_csv(io.BytesIO(self.pairs_csv), dtype={"frame": "int64", "a": "int64", "b": "int64"})


# A frame's numbers as the report gives them (sw/run/run_report.cpp, its keys in order), and each
# baseline's times of a frame: the columns of a run of no frames too.
FRAME_COLUMNS = ("boxes_sent", "compute_cycles", "compute_ns", "driver_ns", "energy_bus_j", "energy_dynamic_j",
                 "energy_host_j", "energy_j", "energy_static_j", "extra_driver_ns", "extra_pairs",
                 "extra_readback_ns", "extra_share", "frame", "irq_ns", "latency_ns", "load_wait_slots", "objects",
                 "overflow_pauses", "overlap_ns", "pairs", "readback_bytes", "readback_ns", "reference_pairs",
                 "sim_wall_native_ns", "stall_cycles", "start_ns", "sweep_cycles", "timeouts_recovered",
                 "total_ns", "upload_bytes", "upload_ns")
BASELINE_TIMES = ("host_ns", "involuntary_switches", "migrated", "native_ns", "probe_native_ns", "wall_native_ns")


def _dtype(column):
    if column.endswith("_migrated"):
        return "bool"
    return "float64" if column.endswith(("_ns", "_j")) or column == "extra_share" else "int64"


def frames_table(frames, baselines=()):
    """The report's frames as a DataFrame, each baseline's nested times flattened into columns;
    a run of no frames has the same columns, typed."""
    rows = []
    for frame in frames:
        row = {key: value for key, value in frame.items() if key != "baselines"}
        for name, times in frame.get("baselines", {}).items():
            row.update({f"{name}_{key}": value for key, value in times.items()})
        rows.append(row)
    if rows:
        return pd.DataFrame(rows)
    columns = list(FRAME_COLUMNS) + [f"{name}_{key}" for name in baselines for key in BASELINE_TIMES]
    return pd.DataFrame({column: pd.Series(dtype=_dtype(column)) for column in columns})
