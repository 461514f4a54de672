"""cdvp.settings() and cdvp.presets(): the settings table and the board presets."""

import json
import subprocess

import pandas as pd

import cdvp


def test_settings_hold_every_setting_with_its_unit_default_range_and_flag():
    table = cdvp.settings().set_index("name")
    assert table.index.is_unique
    m = table.loc["board.m"]
    assert (m["type"], m["default"], m["min"], m["max"], m["flag"]) == ("integer", 8, 1, 32, "--m")
    assert table.loc["board.clock_mhz", "unit"] == "MHz"
    assert table.loc["bus.type", "choices"] == ["ideal", "pci", "pcie"]
    assert table["source"].str.len().min() > 0, "every default names its source"


def test_settings_match_the_command():

    shown = json.loads(subprocess.run([cdvp.find_binary(), "settings", "--json"], capture_output=True,
                                      text=True, check=True).stdout)
    ours = cdvp.settings()
    pd.testing.assert_frame_equal(ours.drop(columns="keyword"), pd.DataFrame(shown, columns=ours.columns.drop("keyword")))
    m = ours.set_index("name").loc["board.m"]
    assert (m["flag"], m["keyword"]) == ("--m", "m")


def test_presets_say_what_each_sets():
    presets = cdvp.presets()
    assert {"adm-xrc-ii", "pcie-gen3-x8"} <= set(presets)
    paper = presets["adm-xrc-ii"]
    assert paper["values"]["bus.type"] == "pci"
    assert paper["values"]["board.clock_mhz"] > 0
    assert presets["pcie-gen3-x8"]["values"]["bus.type"] == "pcie"
    names = set(cdvp.settings()["name"])
    assert all(set(p["values"]) <= names for p in presets.values()), "a preset sets only declared settings"
    assert all(p["description"] for p in presets.values())


def test_the_module_includes_nothing_of_the_command_line():
    import pathlib
    here = pathlib.Path(__file__).resolve().parents[1]
    sources = list(here.glob("*.cpp")) + list(here.glob("*.h"))
    assert sources
    assert not [s.name for s in sources if '#include "sw/cli/' in s.read_text()]
