"""A run's report as Python objects: its config, typed summary, frames and pairs."""

import io
from dataclasses import dataclass, field

import pandas as pd

# The phases of a frame in simulated time, as the report names them (sw/run/report_summary.h).
PHASES = ("upload", "start", "compute", "irq", "readback", "driver", "total")


# The board's energy figures of a summary, as the report names them (docs/energy.md).
ENERGY_FIGURES = ("mean_energy_j", "mean_energy_static_j", "mean_energy_dynamic_j", "mean_energy_bus_j",
                  "mean_energy_host_j", "mean_energy_per_pair_j", "host_package_w")
# A baseline's, on the modelled host; native_energy_j only where RAPL was read.
BASELINE_ENERGY_FIGURES = ("energy_j", "energy_per_pair_j", "energy_ratio", "native_energy_j")


def _energy_stated(summary):
    """Whether the run's board and host state any power (as `cdvp run` prints an energy line):
    a report of none, or of before energy was modelled, has no energy figures."""
    return summary.get("mean_energy_j", 0) > 0 or summary.get("host_package_w", 0) > 0


@dataclass
class Baseline:
    """One software baseline's time a frame on the modelled host, and the board's speedup over it.

    Energy, None when the run states no power: energy_j (J a frame on the modelled host, its
    stated host.package_w times mean_host_ns), energy_per_pair_j (J a pair), energy_ratio (its
    energy over the board's; above 1 the board takes less), native_energy_j (J a frame of this
    machine's package, measured by RAPL; None where it could not be read)."""

    mean_host_ns: float
    p50_host_ns: float
    p99_host_ns: float
    max_host_ns: float
    mean_native_ns: float
    host_factor: float
    speedup: float
    energy_j: float = None
    energy_per_pair_j: float = None
    energy_ratio: float = None
    native_energy_j: float = None

    @classmethod
    def from_json(cls, baseline, stated):
        times = {key: baseline[key] for key in cls.__dataclass_fields__ if key not in BASELINE_ENERGY_FIGURES}
        energy = {key: baseline.get(key) for key in BASELINE_ENERGY_FIGURES} if stated else {}
        return cls(**times, **energy)


@dataclass
class Summary:
    """The report's summary: means over the frames after the warm-up (simulated time unless _native).

    The board's energy a frame, means over the same frames (docs/energy.md), each None when the
    run states no power (no --board): mean_energy_j (J a frame: the four parts' sum),
    mean_energy_static_j (J: the device's quiescent power over the frame's time),
    mean_energy_dynamic_j (J: its logic, block RAM and I/O switching), mean_energy_bus_j (J: the
    bus while it moves the frame's data), mean_energy_host_j (J: the host's package through the
    frame), mean_energy_per_pair_j (J a pair found) and host_package_w (W: the host's stated
    package power behind the host part and each baseline's energy)."""

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
    # The board ran at a clock beyond its estimated Fmax (ignore_timing=True): the line it would
    # otherwise have been refused with ("": the clock is met, or no device family is set).
    timing_warning: str = ""
    mean_energy_j: float = None
    mean_energy_static_j: float = None
    mean_energy_dynamic_j: float = None
    mean_energy_bus_j: float = None
    mean_energy_host_j: float = None
    mean_energy_per_pair_j: float = None
    host_package_w: float = None

    @classmethod
    def from_json(cls, summary):
        stated = _energy_stated(summary)
        baselines = {name: Baseline.from_json(b, stated) for name, b in summary["baselines"].items()}
        energy = {key: summary[key] for key in ENERGY_FIGURES} if stated else {}
        return cls(frames=summary["frames"], warmup_frames=summary["warmup_frames"],
                   frames_in_means=summary["frames_in_means"], too_few_frames=summary["too_few_frames"],
                   pairs=summary["pairs"],
                   mean_phase_ns={phase: summary[f"mean_{phase}_ns"] for phase in PHASES},
                   total_ns={stat: summary[f"{stat}_total_ns"] for stat in ("mean", "p50", "p99", "max")},
                   mean_sim_wall_native_ns=summary["mean_sim_wall_native_ns"],
                   baselines=baselines, extra_pairs=summary["extra_pairs"],
                   best_software=summary.get("best_software", ""),
                   timing_warning=summary.get("timing_warning", ""), **energy)


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
